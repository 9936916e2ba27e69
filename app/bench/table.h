// A results table of the benchmark: named columns, rows of cells that keep both the number (for
// the CSV, full precision) and how to show it (for results.md). One type for both outputs keeps
// the CSV and the markdown table of an experiment from drifting apart.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace app::bench {

struct Cell {
  std::string text;   // as shown in markdown
  std::string value;  // as written to CSV (full precision; empty for a missing value)
};

Cell text_cell(const std::string& text);
// Fixed decimals in markdown ("n/a" for NaN), %.6g in CSV (empty for NaN).
Cell number_cell(double value, int decimals);
// Thousands separators in markdown ("16,384").
Cell count_cell(std::uint64_t value);
// "132x" style ratios; decimals chosen by size.
Cell ratio_cell(double value);

struct Column {
  std::string csv_name;  // snake_case, the CSV header
  std::string header;    // markdown header
  bool markdown = true;  // false: in the CSV only (results.md keeps to what reads at a glance)
};

struct Table {
  std::vector<Column> columns;
  std::vector<std::vector<Cell>> rows;
};

std::string table_csv(const Table& table);
std::string table_markdown(const Table& table);

// Number formatting shared with the report text.
std::string format_fixed(double value, int decimals);
std::string format_count(std::uint64_t value);
std::string format_ratio(double value);
std::string format_bytes(double bytes);

}  // namespace app::bench
