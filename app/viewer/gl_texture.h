// The viewer's OpenGL calls outside Dear ImGui's backend: one RGBA texture that shows the render
// (re-uploaded when the picture changes) and reading the finished window back for screenshots.
// Everything here runs on the UI thread with the window's GL 3.3 core context current.
#pragma once

#include <cstdint>
#include <vector>

namespace app::viewer {

struct GlTexture {
  unsigned int id = 0;
  int width = 0;
  int height = 0;
};

// Creates the texture on first use or when the size changes; nearest filtering shows pixels.
void upload_texture(GlTexture& texture, int width, int height,
                    const std::vector<std::uint8_t>& rgba);
void destroy_texture(GlTexture& texture);

// The back buffer (the frame just drawn, before the swap) as 8-bit RGB, top row first.
std::vector<std::uint8_t> read_window_rgb8(int width, int height);

}  // namespace app::viewer
