#!/usr/bin/env bash
# Runs the scene-file fuzzer for a bounded time (default 60 s) from a seed corpus of the exported
# built-in scenes and the crash regressions. Usage: run.sh LEVRT FUZZER [SECONDS]. Exits non-zero
# on any crash, leak or sanitizer report; the failing input is left in the working folder.
set -euo pipefail
levrt=$1
fuzzer=$2
seconds=${3:-60}
here=$(cd "$(dirname "$0")" && pwd)
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
"$levrt" export --scene building --level 1 --out "$corpus/building1.json"
"$levrt" export --scene maze --level 1 --out "$corpus/maze1.json"
"$levrt" export --scene hall --level 3 --out "$corpus/hall3.json"
cp "$here"/regressions/* "$corpus"/ 2>/dev/null || true
"$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=20 -max_len=1048576 \
  -print_final_stats=1 "$corpus"
