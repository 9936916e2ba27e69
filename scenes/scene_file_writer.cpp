// scene_file_json (scene_file.h): a scene description written as a scene file, every float as the
// shortest decimal that reads back as the same float, short arrays of numbers on one line.
#include <charconv>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scenes/scene_file.h"
#include "scenes/scene_validation.h"

namespace scenes {
namespace {

using ordered = nlohmann::ordered_json;

// The shortest decimal that reads back (as a double, then a float) as exactly this float.
double exact_number(float f) {
  char buffer[64];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), f);
  double d = 0.0;
  const std::from_chars_result back = std::from_chars(buffer, r.ptr, d);
  if (r.ec != std::errc() || back.ec != std::errc() || static_cast<float>(d) != f)
    return static_cast<double>(f);
  return d;
}

ordered vec3_json(const glm::vec3& v) {
  return ordered::array({exact_number(v.x), exact_number(v.y), exact_number(v.z)});
}

class Writer {
 public:
  explicit Writer(const SceneDescription& scene) : scene_(scene) {}

  ordered write() const {
    ordered doc;
    doc["levrt_scene"] = kSceneFileVersion;
    doc["name"] = scene_.name;
    doc["level"] = scene_.level;
    const renderer::Camera& c = scene_.camera;
    doc["camera"] = {{"position", vec3_json(c.position)},
                     {"target", vec3_json(c.target)},
                     {"up", vec3_json(c.up)},
                     {"fov_degrees", exact_number(c.vertical_fov_deg)}};
    if (c.orthographic())
      doc["camera"]["orthographic_half_height"] = exact_number(c.orthographic_half_height);
    doc["ambient"] = vec3_json(scene_.ambient);
    doc["background"] = vec3_json(scene_.background);
    doc["materials"] = ordered::array();
    for (const NamedMaterial& nm : scene_.materials) {
      const renderer::Material& m = nm.material;
      doc["materials"].push_back({{"name", nm.name},
                                  {"colour", vec3_json(m.colour)},
                                  {"ka", exact_number(m.ka)},
                                  {"kd", exact_number(m.kd)},
                                  {"ks", exact_number(m.ks)},
                                  {"shininess", exact_number(m.shininess)},
                                  {"kr", exact_number(m.kr)},
                                  {"kt", exact_number(m.kt)},
                                  {"ior", exact_number(m.ior)}});
    }
    doc["masters"] = ordered::array();
    for (const Master& m : scene_.masters)
      doc["masters"].push_back({{"name", m.name}, {"node", node(m.node)}});
    doc["root"] = node(scene_.root);
    return doc;
  }

 private:
  const std::string& material(std::uint32_t index) const { return scene_.materials[index].name; }

  ordered node(const SceneNode& n) const {
    ordered j;
    j["type"] = node_type_name(n.data);
    if (const auto* a = std::get_if<Affine>(&n.data)) {
      if (a->translate != glm::vec3(0.0f)) j["translate"] = vec3_json(a->translate);
      if (a->rotate_degrees != 0.0f) {
        j["rotate"] = {{"axis", vec3_json(a->rotate_axis)},
                       {"degrees", exact_number(a->rotate_degrees)}};
      }
      if (a->scale != 1.0f) j["scale"] = exact_number(a->scale);
      j["child"] = node(n.children[0]);
    } else if (std::holds_alternative<Union>(n.data)) {
      j["children"] = ordered::array();
      for (const SceneNode& c : n.children) j["children"].push_back(node(c));
    } else if (const auto* in = std::get_if<Instance>(&n.data)) {
      j["master"] = scene_.masters[in->master].name;
    } else if (const auto* s = std::get_if<SphereShape>(&n.data)) {
      j["material"] = material(s->material);
      j["centre"] = vec3_json(s->centre);
      j["radius"] = exact_number(s->radius);
    } else if (const auto* b = std::get_if<BoxShape>(&n.data)) {
      j["material"] = material(b->material);
      j["lo"] = vec3_json(b->lo);
      j["hi"] = vec3_json(b->hi);
    } else if (const auto* c = std::get_if<CylinderShape>(&n.data)) {
      j["material"] = material(c->material);
      j["a"] = vec3_json(c->a);
      j["b"] = vec3_json(c->b);
      j["radius"] = exact_number(c->radius);
      j["segments"] = c->segments;
    } else if (const auto* q = std::get_if<QuadShape>(&n.data)) {
      j["material"] = material(q->material);
      j["corner"] = vec3_json(q->corner);
      j["edge_u"] = vec3_json(q->edge_u);
      j["edge_v"] = vec3_json(q->edge_v);
    } else if (const auto* p = std::get_if<PointLightSource>(&n.data)) {
      j["intensity"] = vec3_json(p->intensity);
      if (std::isfinite(p->range)) j["range"] = exact_number(p->range);
    } else if (const auto* sp = std::get_if<SpotLightSource>(&n.data)) {
      j["intensity"] = vec3_json(sp->intensity);
      j["cone_degrees"] = exact_number(sp->cone_degrees);
      j["dropoff"] = exact_number(sp->dropoff);
      if (std::isfinite(sp->range)) j["range"] = exact_number(sp->range);
      if (!(sp->inner_cone_degrees < 0.0f))
        j["inner_cone_degrees"] = exact_number(sp->inner_cone_degrees);
    } else if (std::holds_alternative<MeshShape>(n.data)) {
      throw std::invalid_argument(std::string(kMeshNotWritable));
    }
    return j;
  }

  const SceneDescription& scene_;
};

bool is_scalar_array(const ordered& j) {
  if (!j.is_array()) return false;
  for (const ordered& e : j) {
    if (e.is_structured()) return false;
  }
  return true;
}

// Indented like dump(2), but arrays of numbers stay on one line ([x, y, z]).
void print(const ordered& j, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& item : j.items()) {
      if (!first) out += ",\n";
      first = false;
      out += pad + ordered(item.key()).dump() + ": ";
      print(item.value(), indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array() && !j.empty() && !is_scalar_array(j)) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (i > 0) out += ",\n";
      out += pad;
      print(j[i], indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else if (j.is_array()) {
    out += "[";
    for (std::size_t i = 0; i < j.size(); ++i) out += (i > 0 ? ", " : "") + j[i].dump();
    out += "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string scene_file_json(const SceneDescription& scene) {
  validate_description(scene);
  if (!scene.directional_lights.empty())
    throw std::invalid_argument(std::string(kDirectionalNotWritable));
  std::string out;
  print(Writer(scene).write(), 0, out);
  out += "\n";
  return out;
}

}  // namespace scenes
