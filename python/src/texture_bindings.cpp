// Normal maps as (H, W, 3) float32 arrays (row 0 = the image's top row, as in a PNG file):
// procedural generators, PNG loading, and the flat-patch friction cone of `asperity cone`.
#include <filesystem>

#include "asperity/error.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/sampler/friction_settings.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/texture/png_io.hpp"
#include "bindings.hpp"

namespace asperity::python {
namespace {

// NormalMap rows are stored bottom-up (OpenGL); the array's rows go top-down.
py::array_t<float> toArray(const NormalMap& map) {
  const int w = map.width(), h = map.height();
  py::array_t<float> out(
      {static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w), py::ssize_t{3}});
  auto o = out.mutable_unchecked<3>();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int k = 0; k < 3; ++k) o(h - 1 - j, i, k) = map.at(i, j)[k];
  return out;
}

// An (H, W, 3) array of unit-ish vectors back into a NormalMap (renormalised).
NormalMap fromArray(const py::handle& value, const char* name) {
  const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 3 || a.shape(2) != 3 || a.shape(0) < 1 || a.shape(1) < 1)
    throwType(std::string(name) + " must be a path or an (H, W, 3) array");
  if (a.shape(0) > kMaxTextureSize || a.shape(1) > kMaxTextureSize)
    throwValue(std::string(name) + ": larger than 8192 texels per side");
  const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  NormalMap map(w, h);
  auto in = a.unchecked<3>();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Vec3f m(in(h - 1 - j, i, 0), in(h - 1 - j, i, 1), in(h - 1 - j, i, 2));
      if (!m.allFinite() || !(m.norm() > 1e-6f) || m.z() < 0.0f)
        throwValue(std::string(name) + ": texel (" + std::to_string(h - 1 - j) + ", " +
                   std::to_string(i) + ") is not a normal with z >= 0");
      map.at(i, j) = m.normalized();
    }
  return map;
}

// A PNG file name, checked for existence first (FileNotFoundError).
NormalMap loadPng(const std::string& path, bool directx) {
  if (!std::filesystem::is_regular_file(path))
    throwFileNotFound(path + ": cannot open (missing or unreadable)");
  NormalMapStats stats;
  NormalMap map =
      loadNormalMapPng(path, directx ? GreenConvention::DirectX : GreenConvention::OpenGL, &stats);
  // Texels that are not normals read flat (SPEC 10), with a UserWarning.
  Diagnostics diagnostics;
  diagnostics.setSink(warn);
  warnInvalidTexels(path, stats, diagnostics);
  return map;
}

// A path or an array.
NormalMap mapArg(const py::handle& value, const char* name) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return loadPng(py::str(py::module_::import("os").attr("fspath")(value)), false);
  return fromArray(value, name);
}

py::array_t<float> generate(const std::string& name, int size, uint64_t seed,
                            const py::kwargs& params) {
  GeneratorSpec spec;
  spec.name = name;
  spec.size = size;
  spec.seed = seed;
  if (size < 1 || size > kMaxTextureSize)
    throwValue("size must be in 1..8192, got " + std::to_string(size));
  // Parameters as the CLI's text (numbers and paths alike).
  for (const auto& [key, value] : params) {
    if (py::isinstance<py::bool_>(value))
      throwType(key.cast<std::string>() + " must be a number or a path, got a bool");
    spec.params[key.cast<std::string>()] = py::str(value).cast<std::string>();
  }
  NormalMap map;
  {
    py::gil_scoped_release release;
    map = generateNormalMap(spec);
  }
  return toArray(map);
}

py::dict cone(const py::handle& b, const py::handle& a, int directions, double k_a, double k_b,
              double mu0, double mu_max) {
  if (const std::string bad = friction_range::directions.check(directions); !bad.empty())
    throwValue("directions " + bad);
  if (!(k_a >= 0.0 && k_a <= 1000.0) || !(k_b >= 0.0 && k_b <= 1000.0) ||
      !(mu0 >= 0.0 && mu0 <= 1000.0))
    throwValue("k_a, k_b and mu0 must be finite numbers in [0, 1000]");
  if (const std::string bad = friction_range::mu_max.check(mu_max); !bad.empty())
    throwValue("mu_max " + bad);
  const NormalMap map_b = mapArg(b, "b");
  std::optional<NormalMap> map_a;
  if (!a.is_none()) map_a = mapArg(a, "a");
  // Eq. 7 over a flat patch covering every texel, then the box (Eq. 9).
  PatchConeOptions opt;
  opt.directions = directions;
  opt.gains = {mu0, k_a, k_b};
  opt.mu_max = static_cast<float>(mu_max);
  const DirectionalMu mu = flatPatchCone(map_a ? &*map_a : nullptr, map_b, opt);
  const BoxLimit box = BoxLimit::fromDirectional(mu);
  py::array_t<double> angles(directions), values(directions);
  for (int k = 0; k < directions; ++k) {
    angles.mutable_at(k) = 360.0 * k / directions;
    values.mutable_at(k) = mu.mu[static_cast<size_t>(k)];
  }
  py::dict box_dict;
  box_dict["+t"] = box.mu_pos_t, box_dict["+b"] = box.mu_pos_b;
  box_dict["-t"] = box.mu_neg_t, box_dict["-b"] = box.mu_neg_b;
  py::dict d;
  d["angles_deg"] = angles, d["mu"] = values, d["box"] = box_dict;
  return d;
}

}  // namespace

void bindTexture(py::module_& m) {
  m.def("generate_texture", &generate, py::arg("name"), py::kw_only(), py::arg("size") = 256,
        py::arg("seed") = 1,
        "A procedural normal map (`asperity texture --list` names the generators and their "
        "parameters, given here as keywords) as an (H, W, 3) float32 array of unit normals, "
        "row 0 at the top. The same seed gives the same array as the CLI's PNG.");
  m.def(
      "load_normal_map",
      [](const py::handle& path, bool directx) {
        return toArray(loadPng(py::str(py::module_::import("os").attr("fspath")(path)), directx));
      },
      py::arg("path"), py::kw_only(), py::arg("directx") = false,
      "Reads a PNG normal map (8 or 16 bits) as an (H, W, 3) float32 array, row 0 at the top. "
      "directx=True reads green as -bitangent.");
  m.def("cone", &cone, py::arg("b"), py::arg("a") = py::none(), py::kw_only(),
        py::arg("directions") = 16, py::arg("k_a") = 1.0, py::arg("k_b") = 1.0,
        py::arg("mu0") = 0.0, py::arg("mu_max") = static_cast<double>(kDefaultMuMax),
        "The friction limit surface of a flat patch over two normal maps (paper Fig. 8, "
        "`asperity cone`): b and a are paths or (H, W, 3) arrays (a flat when None). Returns "
        "{'angles_deg': (N,), 'mu': (N,), 'box': {'+t', '+b', '-t', '-b'}}.");
}

}  // namespace asperity::python
