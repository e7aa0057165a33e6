// `asperity texture`: writes any procedural generator's normal map to a PNG, or lists the
// generators and their parameters. Generator parameters are dynamic (`--sx 0.1`), collected
// from CLI11's extras and checked by generateNormalMap.
#include <iostream>
#include <memory>

#include "asperity/error.hpp"
#include "asperity/texture/generators.hpp"
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
  if (opt.out.empty()) throw Error("texture: --out FILE.png is required");
  spec.size = opt.size;
  spec.seed = opt.seed;
  const NormalMap map = generateNormalMap(spec);

  PngWriteOptions png;
  png.bits = opt.bits;
  png.green = opt.directx ? GreenConvention::DirectX : GreenConvention::OpenGL;
  saveNormalMapPng(map, opt.out, png);
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

  sub->callback([opt, sub]() { runTexture(*opt, sub->remaining()); });
}

}  // namespace asperity::cli
