// `asperity texture`: writes any procedural generator's normal map to a PNG, or lists the
// generators and their parameters. Generator parameters are dynamic (`--sx 0.1`), collected
// from CLI11's extras and checked by generateNormalMap.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "asperity/texture/height_map.hpp"
#include "asperity/texture/map_inspect.hpp"
#include "asperity/texture/png_io.hpp"
#include "cli_common.hpp"

namespace asperity::cli {
namespace {

struct TextureOptions {
  bool list = false;
  std::string generator;
  int size = 256;
  uint64_t seed = 1;
  std::string out;
  int bits = 8;
  bool directx = false;
  std::string height_out;       // --height FILE.png: the generator's heights, 16-bit grey
  double texture_size = 0.25;   // metres per repeat, for the heights' physical scale
};

// One line per parameter: name, default, range (numbers) and doc.
void printCatalog(std::ostream& os) {
  for (const GeneratorInfo& g : generatorCatalog()) {
    os << g.name << "  " << g.doc << '\n';
    for (const GeneratorParam& p : g.params) {
      os << "  --" << p.name << "  default " << (p.default_value.empty() ? "''" : p.default_value);
      if (p.kind == "number")
        os << "  range [" << p.min << ", " << p.max << "]";
      else
        os << "  (" << p.kind << ")";
      os << "  " << p.doc << '\n';
    }
  }
}

// Turns the leftover arguments into generator parameters: `--name value` or `--name=value`.
std::map<std::string, std::string> parseGeneratorParams(const std::vector<std::string>& extras) {
  std::map<std::string, std::string> params;
  for (size_t i = 0; i < extras.size(); ++i) {
    const std::string& arg = extras[i];
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0)
      throw Error("texture: unexpected argument '" + arg +
                  "' (generator parameters are written --name value)");
    std::string name = arg.substr(2);
    std::string value;
    if (const size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else if (i + 1 < extras.size()) {
      value = extras[++i];
    } else {
      throw Error("texture: generator parameter --" + name + " has no value");
    }
    if (!params.emplace(name, value).second)
      throw Error("texture: generator parameter --" + name + " is given twice");
  }
  return params;
}

// The subcommand's action, run after CLI11 has parsed and validated the fixed options.
void runTexture(const TextureOptions& opt, const std::vector<std::string>& extras) {
  if (opt.list) {
    if (!extras.empty()) throw Error("texture --list: unexpected argument '" + extras[0] + "'");
    printCatalog(std::cout);
    return;
  }
  if (opt.generator.empty())
    throw Error("texture: missing GENERATOR (see `asperity texture --list`)");
  GeneratorSpec spec;
  spec.name = opt.generator;
  spec.params = parseGeneratorParams(extras);
  if (opt.out.empty() && opt.height_out.empty())
    throw Error("texture: --out FILE.png (normals) or --height FILE.png (heights) is required");
  spec.size = opt.size;
  spec.seed = opt.seed;
  if (!opt.height_out.empty()) {
    // The scale goes into the PNG's text chunk and onto stdout, for the surface's height_scale.
    const double scale =
        saveHeightMapPng(generateHeightMap(spec, opt.texture_size), opt.height_out);
    std::printf("%s: height_scale %.9g m (texture_size %.9g m)\n", opt.height_out.c_str(), scale,
                opt.texture_size);
  }
  if (opt.out.empty()) return;
  const NormalMap map = generateNormalMap(spec);

  PngWriteOptions png;
  png.bits = opt.bits;
  png.green = opt.directx ? GreenConvention::DirectX : GreenConvention::OpenGL;
  saveNormalMapPng(map, opt.out, png);
}

// Greyscale PNG: a height map. Its roughness at physical scale (SPEC 13).
void inspectHeights(const std::string& file, double height_scale, double texture_size,
                    bool json) {
  HeightMapInfo info;
  const HeightMap map = loadHeightMap(file, height_scale, &info);
  const HeightStats st = heightStats(map, texture_size);
  if (json) {
    nlohmann::ordered_json j;
    j["kind"] = "height_map";
    j["width"] = map.width;
    j["height"] = map.height;
    j["bits"] = info.bits;
    j["height_scale"] = info.height_scale;
    j["texture_size"] = texture_size;
    j["ra"] = st.ra;
    j["rq"] = st.rq;
    j["rms_slope"] = st.rms_slope;
    j["correlation_length"] = st.correlation_length;
    std::cout << j.dump(2) << '\n';
    return;
  }
  char line[512];
  std::snprintf(line, sizeof(line),
                "%s\nheight map: %d x %d, %d bits, height_scale %.6g m (%s), texture_size %.6g m\n"
                "Ra %.6g m  Rq %.6g m  rms slope %.6g  correlation length %.6g m\n",
                file.c_str(), map.width, map.height, info.bits, info.height_scale,
                info.scale_from_file ? "from the file" : "given", texture_size, st.ra, st.rq,
                st.rms_slope, st.correlation_length);
  std::cout << line;
}

// True for a PNG whose colour type is grey or grey + alpha (byte 25 of the file).
bool isGreyPng(const std::vector<uint8_t>& bytes) {
  static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return bytes.size() > 25 && std::equal(sig, sig + 8, bytes.begin()) &&
         (bytes[25] == 0 || bytes[25] == 4);
}

// `texture inspect FILE [--json]`: size, bits, invalid texels, green verdict, slope, box cone.
void runInspect(const std::string& file, bool json) {
  // Decoded as OpenGL; the verdict says whether DirectX fits better.
  NormalMapStats stats;
  const std::optional<std::vector<uint8_t>> bytes = readFileBytes(file);
  if (!bytes) throw Error("texture inspect: cannot open '" + file + "'");
  const NormalMap map = decodeNormalMap(*bytes, file, GreenConvention::OpenGL, 1.0, &stats);
  const GreenFit fit = judgeGreenConvention(map);
  const double slope = meanSlope(map);
  // The whole-texture box cone against a flat partner (as `asperity cone FILE`).
  const BoxLimit box = BoxLimit::fromDirectional(flatPatchCone(nullptr, map, PatchConeOptions{}));
  if (json) {
    nlohmann::ordered_json j;
    j["width"] = map.width();
    j["height"] = map.height();
    j["bits"] = stats.bits;
    j["invalid_fraction"] = stats.invalidFraction();
    j["convention"] = verdictName(fit.verdict);
    j["mean_slope"] = slope;
    j["box"] = {
        {"+t", box.mu_pos_t}, {"+b", box.mu_pos_b}, {"-t", box.mu_neg_t}, {"-b", box.mu_neg_b}};
    std::cout << j.dump(2) << '\n';
    return;
  }
  char line[256];
  std::snprintf(line, sizeof(line),
                "%s\nsize: %d x %d, %d bits\ninvalid texels: %.2f %% (treated as flat)\n"
                "convention: %s (RMS curl as OpenGL %.4g, as DirectX %.4g)\nmean slope: %.4f\n"
                "box: +t %.4f  +b %.4f  -t %.4f  -b %.4f\n",
                file.c_str(), map.width(), map.height(), stats.bits,
                100.0 * stats.invalidFraction(), verdictName(fit.verdict), fit.curl_opengl,
                fit.curl_directx, slope, box.mu_pos_t, box.mu_pos_b, box.mu_neg_t, box.mu_neg_b);
  std::cout << line;
}

// `texture inspect FILE [--json]` reads a map instead of writing one: a normal map, or a height
// map (grey PNG, .exr), whose roughness needs the physical scale.
CLI::App* registerInspect(CLI::App& sub) {
  struct InspectOptions {
    std::string file;
    bool json = false;
    double height_scale = 0.0;
    double texture_size = 0.25;
  };
  auto opt = std::make_shared<InspectOptions>();
  CLI::App* inspect = sub.add_subcommand("inspect",
                                         "Report a normal map (PNG, JPEG): size, bits, texels "
                                         "that are not normals, the green convention its slopes "
                                         "fit, mean slope, box cone; or a height map (grey PNG, "
                                         ".exr): Ra, Rq, rms slope, correlation length");
  inspect->add_option("file", opt->file, "Normal map (PNG, JPEG) or height map")->required();
  inspect->add_flag("--json", opt->json, "Print JSON");
  inspect->add_option("--height-scale", opt->height_scale,
                      "Height map: metres per full range (default: the one stored in the file)")
      ->check(CLI::NonNegativeNumber);
  inspect->add_option("--texture-size", opt->texture_size, "Height map: metres covered by the map")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  inspect->callback([opt]() {
    const std::optional<std::vector<uint8_t>> bytes = readFileBytes(opt->file);
    const std::string tail = opt->file.size() > 4 ? opt->file.substr(opt->file.size() - 4) : "";
    if (tail == ".exr" || tail == ".EXR" || (bytes && isGreyPng(*bytes)))
      inspectHeights(opt->file, opt->height_scale, opt->texture_size, opt->json);
    else
      runInspect(opt->file, opt->json);
  });
  return inspect;
}

}  // namespace

void registerTextureCommand(CLI::App& app) {
  auto opt = std::make_shared<TextureOptions>();
  CLI::App* sub = app.add_subcommand(
      "texture",
      "Write a procedural normal map to a PNG: texture GENERATOR [--PARAM VALUE ...] --out "
      "FILE.png (see --list for generators and their parameters)");
  sub->allow_extras();

  // Fixed options; everything else is a generator parameter.
  sub->add_flag("--list", opt->list, "List the generators and their parameters");
  sub->add_option("generator", opt->generator, "Generator name (see --list)");
  sub->add_option("--size", opt->size, "Texels per side (square)")
      ->check(CLI::Range(1, kMaxTextureSize))
      ->capture_default_str();
  sub->add_option("--seed", opt->seed, "Random seed")->check(notNegative())->capture_default_str();
  sub->add_option("--out", opt->out, "Output PNG file");
  sub->add_option("--bits", opt->bits, "Bits per channel")
      ->check(CLI::IsMember({8, 16}))
      ->capture_default_str();
  sub->add_flag("--directx", opt->directx, "Write green as -bitangent (DirectX convention)");
  sub->add_option("--height", opt->height_out,
                  "Also (or only) write the generator's heights as a 16-bit grey PNG; the "
                  "height_scale (metres per full range) is stored in it and printed");
  sub->add_option("--texture-size", opt->texture_size,
                  "Metres covered by the texture, for --height's physical scale")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  CLI::App* inspect = registerInspect(*sub);

  sub->callback([opt, sub, inspect]() {
    if (inspect->parsed()) return;
    runTexture(*opt, sub->remaining());
  });
}

}  // namespace asperity::cli
