// The viewer's frame loop: a GLFW window with a GL 3.3 core context, Dear ImGui's panel on the
// left and the render on the right. Each frame it applies scripted changes, takes the worker's
// status and finished tiles (never waiting for the tracer), draws the panel, posts at most one
// request, re-uploads the texture when the picture changed, and paces itself to about 60 fps.
// In scripted mode (--frames N) it exits after N frames, optionally writing the whole window.
#pragma once

#include "app/settings.h"
#include "app/viewer/viewer_flags.h"

namespace app::viewer {

// Throws NoDisplayError without a display and UsageError for bad viewer flags.
int run_viewer(const Settings& settings, const ViewerFlags& flags);

}  // namespace app::viewer
