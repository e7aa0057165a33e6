// The C face of ContactFriction (asperity/c/contact_friction.h): plain structs in and out,
// every exception turned into a status and a message kept on the handle.
#include "asperity/c/contact_friction.h"

#include <cstring>
#include <filesystem>
#include <new>
#include <sstream>
#include <string>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/error.hpp"

struct asperity_friction {
  std::unique_ptr<asperity::ContactFriction> friction;  // null after a failed create
  std::string error;
  std::string warnings;  // asperity_friction_warnings' text
};

namespace {

using namespace asperity;

// A file that cannot be read (ASPERITY_ERROR_NOT_FOUND).
struct NotFound : Error {
  using Error::Error;
};

Vec3 vec3(const double v[3]) {
  return Vec3(v[0], v[1], v[2]);
}
Quat quat(const double q[4]) {
  return Quat(q[0], q[1], q[2], q[3]);
}

// Runs `work`, turning an exception into a status and the handle's message.
template <class Work>
asperity_status guarded(asperity_friction* handle, const Work& work) {
  if (!handle) return ASPERITY_ERROR_INVALID_ARGUMENT;
  try {
    if (!handle->friction) throw Error("this handle failed to be created: " + handle->error);
    handle->error.clear();
    work(*handle->friction);
    return ASPERITY_OK;
  } catch (const NotFound& e) {
    handle->error = e.what();
    return ASPERITY_ERROR_NOT_FOUND;
  } catch (const Error& e) {
    handle->error = e.what();
    return ASPERITY_ERROR_INVALID_ARGUMENT;
  } catch (const std::exception& e) {
    handle->error = e.what();
    return ASPERITY_ERROR_FAILED;
  }
}

// "gen:NAME" or "gen:NAME:key=value,key=value" names a generator; anything else a PNG file.
SurfaceSource surfaceSource(const char* spec) {
  SurfaceSource source;
  if (!spec || !*spec) return source;
  const std::string text(spec);
  if (text.rfind("gen:", 0) != 0) {
    if (!std::filesystem::exists(text)) throw NotFound("normal map '" + text + "' not found");
    source.normal_map_file = text;
    return source;
  }
  const std::string rest = text.substr(4);
  const size_t colon = rest.find(':');
  source.generator.name = rest.substr(0, colon);
  if (colon == std::string::npos) return source;
  std::stringstream params(rest.substr(colon + 1));
  for (std::string item; std::getline(params, item, ',');) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw Error("generator '" + text + "': parameter '" + item + "' needs key=value");
    source.generator.params[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return source;
}

// A triangle mesh from the C arrays.
std::shared_ptr<const TriangleMeshData> meshOf(const asperity_shape& s) {
  if (!s.vertices || !s.triangles || s.vertex_count == 0 || s.triangle_count == 0)
    throw Error("a mesh shape needs vertices and triangles");
  auto mesh = std::make_shared<TriangleMeshData>();
  for (size_t i = 0; i < s.vertex_count; ++i) {
    mesh->vertices.emplace_back(s.vertices[3 * i], s.vertices[3 * i + 1], s.vertices[3 * i + 2]);
    if (s.uvs) mesh->uvs.emplace_back(s.uvs[2 * i], s.uvs[2 * i + 1]);
  }
  for (size_t k = 0; k < s.triangle_count; ++k) {
    std::array<int, 3> tri{s.triangles[3 * k], s.triangles[3 * k + 1], s.triangles[3 * k + 2]};
    for (const int v : tri) {
      if (v < 0 || static_cast<size_t>(v) >= s.vertex_count)
        throw Error("mesh triangle " + std::to_string(k) + " names vertex " + std::to_string(v) +
                    " of " + std::to_string(s.vertex_count));
    }
    mesh->triangles.push_back(tri);
  }
  return mesh;
}

Shape shapeOf(const asperity_shape& s, Diagnostics& diagnostics) {
  Shape shape;
  switch (s.type) {
    case ASPERITY_SHAPE_BOX:
      shape.type = ShapeType::Box;
      break;
    case ASPERITY_SHAPE_SPHERE:
      shape.type = ShapeType::Sphere;
      break;
    case ASPERITY_SHAPE_CAPSULE:
      shape.type = ShapeType::Capsule;
      break;
    case ASPERITY_SHAPE_CYLINDER:
      shape.type = ShapeType::Cylinder;
      break;
    case ASPERITY_SHAPE_PLANE:
      shape.type = ShapeType::Plane;
      break;
    case ASPERITY_SHAPE_MESH:
      shape.type = ShapeType::TriangleMesh;
      break;
    default:
      throw Error("unknown shape type " + std::to_string(s.type));
  }
  shape.local = {vec3(s.position), quat(s.rotation).normalized()};
  shape.half_extents = vec3(s.half_extents);
  shape.radius = s.radius;
  shape.half_height = s.half_height;
  shape.plane_normal = vec3(s.plane_normal).normalized();
  shape.plane_offset = s.plane_offset;
  if (shape.type == ShapeType::TriangleMesh) shape.mesh = meshOf(s);
  shape.surface.source = surfaceSource(s.normal_map);
  shape.surface.gain = s.gain;
  shape.surface.texture_size = s.texture_size;
  shape.surface.texture_rotation = s.texture_rotation;
  resolveSurface(shape.surface, diagnostics);
  return shape;
}

ContactFrictionSettings settingsOf(const asperity_friction_settings& s) {
  ContactFrictionSettings out;
  out.friction.directions = s.directions;
  out.friction.mu0 = s.mu0;
  out.friction.patch_width = s.patch_width;
  out.friction.patch_resolution = s.patch_resolution;
  out.friction.reuse_pixels = s.reuse_pixels;
  out.provider = s.provider ? s.provider : "";
  if (s.frame_mode < 0 || s.frame_mode > ASPERITY_FRAME_TEXTURE)
    throw Error("contact friction settings: unknown frame mode " + std::to_string(s.frame_mode));
  out.frame.mode = static_cast<FrameMode>(s.frame_mode);
  out.frame.world_axis = vec3(s.world_axis);
  out.threads = s.threads;
  return out;
}

EngineContact contactOf(const asperity_contact& c) {
  EngineContact e;
  e.object_a = c.object_a;
  e.object_b = c.object_b;
  e.shape_a = c.shape_a;
  e.shape_b = c.shape_b;
  e.point = vec3(c.point);
  e.normal = vec3(c.normal);
  e.depth = c.depth;
  e.key = c.key;
  return e;
}

void copyResult(const ContactFrictionResult& r, asperity_contact_friction& out) {
  for (int k = 0; k < 3; ++k) {
    out.t[k] = r.t[k];
    out.b[k] = r.b[k];
  }
  std::memset(out.mu, 0, sizeof(out.mu));
  for (int k = 0; k < r.mu.count; ++k) out.mu[k] = r.mu.mu[static_cast<size_t>(k)];
  out.directions = r.mu.count;
  out.bounds[0] = r.bounds.mu_pos_t;
  out.bounds[1] = r.bounds.mu_pos_b;
  out.bounds[2] = r.bounds.mu_neg_t;
  out.bounds[3] = r.bounds.mu_neg_b;
  out.symmetric[0] = r.symmetric_t;
  out.symmetric[1] = r.symmetric_b;
  out.fallback = r.fallback ? 1 : 0;
}

}  // namespace

extern "C" {

void asperity_friction_default_settings(asperity_friction_settings* settings) {
  if (!settings) return;
  const ContactFrictionSettings d;
  *settings = {};
  settings->directions = d.friction.directions;
  settings->mu0 = d.friction.mu0;
  settings->patch_width = d.friction.patch_width;
  settings->patch_resolution = d.friction.patch_resolution;
  settings->reuse_pixels = d.friction.reuse_pixels;
  settings->provider = kDefaultFrictionProvider;
  settings->frame_mode = ASPERITY_FRAME_WORLD;
  settings->world_axis[0] = 1.0;
  settings->threads = d.threads;
}

void asperity_friction_default_shape(asperity_shape* shape) {
  if (!shape) return;
  *shape = {};
  shape->type = ASPERITY_SHAPE_BOX;
  shape->rotation[0] = 1.0;
  for (double& h : shape->half_extents) h = 0.1;
  shape->radius = 0.1;
  shape->half_height = 0.1;
  shape->plane_normal[2] = 1.0;
  shape->gain = 1.0;
  shape->texture_size = 0.25;
}

asperity_status asperity_friction_create(const asperity_friction_settings* settings,
                                         asperity_friction** out) {
  if (!out) return ASPERITY_ERROR_INVALID_ARGUMENT;
  *out = new (std::nothrow) asperity_friction;
  if (!*out) return ASPERITY_ERROR_FAILED;
  try {
    if (!settings) throw Error("contact friction settings are null");
    (*out)->friction = std::make_unique<ContactFriction>(settingsOf(*settings));
    return ASPERITY_OK;
  } catch (const std::exception& e) {
    (*out)->error = e.what();
    return ASPERITY_ERROR_INVALID_ARGUMENT;
  }
}

void asperity_friction_destroy(asperity_friction* handle) {
  delete handle;
}

const char* asperity_friction_error(const asperity_friction* handle) {
  return handle ? handle->error.c_str() : "the handle is null";
}

const char* asperity_friction_warnings(asperity_friction* handle) {
  if (!handle) return "";
  handle->warnings.clear();
  if (handle->friction) {
    for (const std::string& w : handle->friction->diagnostics().warnings())
      handle->warnings += w + "\n";
  }
  return handle->warnings.c_str();
}

asperity_status asperity_friction_add_object(asperity_friction* handle, const char* name,
                                             const asperity_shape* shapes, size_t shape_count,
                                             uint32_t* id) {
  return guarded(handle, [&](ContactFriction& f) {
    if (!name || !id || (!shapes && shape_count > 0)) throw Error("add_object: null argument");
    ObjectDesc desc;
    desc.name = name;
    for (size_t i = 0; i < shape_count; ++i)
      desc.shapes.push_back(shapeOf(shapes[i], f.diagnostics()));
    *id = f.addObject(desc);
  });
}

asperity_status asperity_friction_set_state(asperity_friction* handle, uint32_t id,
                                            const double position[3], const double rotation[4],
                                            const double linear_velocity[3],
                                            const double angular_velocity[3]) {
  return guarded(handle, [&](ContactFriction& f) {
    if (!position || !rotation || !linear_velocity || !angular_velocity)
      throw Error("set_state: null argument");
    f.setState(id,
               {{vec3(position), quat(rotation)}, vec3(linear_velocity), vec3(angular_velocity)});
  });
}

asperity_status asperity_friction_compute(asperity_friction* handle,
                                          const asperity_contact* contacts, size_t count,
                                          asperity_contact_friction* out) {
  return guarded(handle, [&](ContactFriction& f) {
    if (count > 0 && (!contacts || !out)) throw Error("compute: null argument");
    std::vector<EngineContact> in(count);
    for (size_t i = 0; i < count; ++i) in[i] = contactOf(contacts[i]);
    const auto results = f.compute(in);
    for (size_t i = 0; i < count; ++i) copyResult(results[i], out[i]);
  });
}

}  // extern "C"
