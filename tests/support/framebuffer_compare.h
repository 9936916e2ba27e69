// Bit-for-bit comparison of two framebuffers: the determinism tests' (threads, tile order) and
// the exactness tests' (lev at tolerance 0 against rt) one notion of "the same image".
#pragma once

#include <cstring>

#include <glm/glm.hpp>

#include "renderer/framebuffer.h"

inline bool bitwise_equal(const renderer::Framebuffer& a, const renderer::Framebuffer& b) {
  return a.radiance_sum.size() == b.radiance_sum.size() &&
         std::memcmp(a.radiance_sum.data(), b.radiance_sum.data(),
                     a.radiance_sum.size() * sizeof(glm::vec3)) == 0 &&
         a.samples == b.samples;
}
