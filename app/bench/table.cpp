#include "app/bench/table.h"

#include <cmath>
#include <cstdio>

namespace app::bench {

std::string format_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string format_count(std::uint64_t value) {
  std::string digits = std::to_string(value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string format_ratio(double value) {
  if (!std::isfinite(value)) return "n/a";
  return format_fixed(value, value >= 100.0 ? 0 : (value >= 10.0 ? 1 : 2)) + "x";
}

std::string format_bytes(double bytes) {
  if (!std::isfinite(bytes)) return "n/a";
  if (bytes >= 1024.0 * 1024.0) return format_fixed(bytes / (1024.0 * 1024.0), 1) + " MB";
  if (bytes >= 1024.0) return format_fixed(bytes / 1024.0, 1) + " KB";
  return format_fixed(bytes, 0) + " B";
}

Cell text_cell(const std::string& text) {
  return {text, text};
}

Cell number_cell(double value, int decimals) {
  if (!std::isfinite(value)) return {"n/a", ""};
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return {format_fixed(value, decimals), buffer};
}

Cell count_cell(std::uint64_t value) {
  return {format_count(value), std::to_string(value)};
}

Cell ratio_cell(double value) {
  if (!std::isfinite(value)) return {"n/a", ""};
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return {format_ratio(value), buffer};
}

namespace {

// RFC 4180: quote a field holding a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::string table_csv(const Table& table) {
  std::string out;
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out += (c ? "," : "") + csv_field(table.columns[c].csv_name);
  out += "\n";
  for (const std::vector<Cell>& row : table.rows) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      out += (c ? "," : "") + csv_field(c < row.size() ? row[c].value : std::string());
    }
    out += "\n";
  }
  return out;
}

std::string table_markdown(const Table& table) {
  std::string header = "|", rule = "|";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (!table.columns[c].markdown) continue;
    header += " " + table.columns[c].header + " |";
    rule += rule.size() == 1 ? "---|" : "---:|";
  }
  std::string out = header + "\n" + rule + "\n";
  for (const std::vector<Cell>& row : table.rows) {
    out += "|";
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (table.columns[c].markdown)
        out += " " + (c < row.size() ? row[c].text : std::string()) + " |";
    }
    out += "\n";
  }
  return out;
}

}  // namespace app::bench
