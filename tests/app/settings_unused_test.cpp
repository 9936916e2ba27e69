// A setting the table calls unused for some settings (SettingSpec::unused_because: the viewer
// greys it out) really does not change what those settings render: for every method that says
// so, the image at two values of its tolerance, relative error or lights per point is the same byte
// for byte; a method that uses one of them renders something else at the other value.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/scene_loading.h"
#include "app/settings.h"
#include "lev/methods.h"
#include "renderer/render.h"

namespace {

std::vector<std::uint8_t> render_rgb8(const app::LoadedScene& loaded, const app::Settings& s) {
  renderer::RenderStatePtr state =
      renderer::make_render_state(loaded.scene, *loaded.rays, app::render_settings_from(s));
  for (int pass = 0; pass < s.image.spp; ++pass) EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::framebuffer_rgb8(renderer::render_framebuffer(*state));
}

bool unused(const std::string& name, const app::Settings& s) {
  const app::SettingSpec* spec = app::find_setting(name);
  return spec->unused_because && spec->unused_because(s) != nullptr;
}

TEST(SettingsUnused, WhatAMethodIgnoresDoesNotChangeItsImage) {
  app::Settings base;
  base.scene.level = 3;
  base.image.width = 40;
  base.image.height = 30;
  base.image.spp = 2;
  const std::unique_ptr<app::LoadedScene> loaded = app::load_scene(base.scene);
  struct Variation {
    std::string name;
    void (*apply)(app::Settings& s);
  };
  const std::vector<Variation> variations = {
      {"tolerance", [](app::Settings& s) { s.method.tolerance = 0.3; }},
      {"relative-error", [](app::Settings& s) { s.method.relative_error = 0.3; }},
      {"lights-per-point", [](app::Settings& s) { s.method.lights_per_point = 7; }},
  };
  int used_and_changed = 0;
  for (const std::string& method : app::method_options()) {
    app::Settings a = base;
    a.method.method = *lev::parse_method(method);
    if (a.method.method == lev::Method::rt) a.method.tolerance = 0.0;
    const std::vector<std::uint8_t> image = render_rgb8(*loaded, a);
    for (const Variation& v : variations) {
      app::Settings b = a;
      v.apply(b);
      const bool same = render_rgb8(*loaded, b) == image;
      if (unused(v.name, a)) {
        EXPECT_TRUE(same) << method << " ignores " << v.name << " but renders differently";
      } else if (!same) {
        ++used_and_changed;
      }
    }
  }
  // The check can fail: some method that uses a setting renders differently at the other value.
  EXPECT_GT(used_and_changed, 3);
}

TEST(SettingsUnused, TheCameraIndexIsAGltfFilesAlone) {
  app::Settings s;
  EXPECT_TRUE(unused("camera", s));
  s.scene.name = "room.gltf";
  EXPECT_FALSE(unused("camera", s));
  s.scene.name = "room.glb";
  EXPECT_FALSE(unused("camera", s));
  EXPECT_FALSE(unused("tolerance", s));  // lev, the default, has one
}

}  // namespace
