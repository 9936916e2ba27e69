// `levrt inspect --pixel X,Y [render flags] [--top N] [--json FILE]`: the pixel inspector headless
// (renderer/pixel_inspection.h). For the pixel's primary hit and each reflected or refracted hit,
// the lights the method shaded and those it culled or clustered, sorted by what they give the
// pixel, as a table on standard output (the top N rows per hit and the totals), and the complete
// lists as JSON through the all-or-none output rule (app/output_files.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "renderer/pixel_inspection.h"

namespace app {

struct InspectFlags {
  std::string pixel;  // "X,Y" as typed
  int top = 20;       // rows per hit in the table
  std::string json;   // the complete lists (empty: none)
};

inline constexpr int kDefaultInspectTop = 20;

// "X,Y", two decimal integers inside width x height; else UsageError naming --pixel.
void parse_inspect_pixel(const std::string& text, int width, int height, int& x, int& y);

// The inspection as JSON (every list complete) and as the table.
nlohmann::ordered_json inspection_json(const renderer::PixelInspection& inspection);
std::string inspection_table(const renderer::PixelInspection& inspection, int top);

int run_inspect(const Settings& settings, const InspectFlags& flags);

}  // namespace app
