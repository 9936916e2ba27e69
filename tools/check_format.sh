#!/usr/bin/env bash
# Fails when a tracked C++ file is not formatted by the project's .clang-format (clang-format 14,
# Debian 12) or has a line over the 100-column limit, naming each file and line. CI runs it first;
# `clang-format -i FILE` fixes the first kind, a raw string split into adjacent literals the second.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h')
status=0
if ! clang-format --dry-run --Werror "${files[@]}"; then
  echo "check_format: the files above are not clang-formatted (clang-format -i FILE)" >&2
  status=1
fi
if awk 'length > 100 { print FILENAME ":" FNR ": " length " columns, over the limit of 100"; bad = 1 }
        END { exit bad }' "${files[@]}" >&2; then :; else
  status=1
fi
[ "$status" -eq 0 ] && echo "check_format: ${#files[@]} files formatted, no line over 100 columns"
exit "$status"
