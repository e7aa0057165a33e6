// `asperity patch SCENE.json --step K [--contact I] --out FILE.png`: the paper's Fig. 7 for one
// contact. The scene runs K steps; contact I of that step is sampled by the CPU reference sampler
// (the OpenGL sampler gives the same numbers) and drawn as each surface's rendered meso normals
// (RGB = 0.5 n + 0.5, contact frame) and its coefficient channels mu_{d_k} (Eq. 5) as greyscale,
// with the contact's mu_d (Eq. 7) printed beside them and on stdout.
#include <cairo.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "cli_common.hpp"

namespace asperity::cli {
namespace {

struct PatchOptions {
  std::string scene;
  int step = 0;
  int contact = 0;
  std::string out;
};

constexpr int kColumns = 9;  // normals + up to 8 channels per row
constexpr int kMargin = 12;
constexpr int kLabel = 18;
constexpr int kText = 300;

// Draws one R x R image at (x, y), `cell` pixels per patch pixel, row 0 at the bottom (-b).
template <class ColourOf>
void drawImage(cairo_t* cr, int x, int y, int r, int cell, ColourOf colour) {
  for (int j = 0; j < r; ++j) {
    for (int i = 0; i < r; ++i) {
      double rgb[3];
      colour(j * r + i, rgb);
      cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
      cairo_rectangle(cr, x + i * cell, y + (r - 1 - j) * cell, cell, cell);
      cairo_fill(cr);
    }
  }
}

void label(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

// Where the figure's panels go: per surface, panel 0 (normals) then one per channel, in rows
// of `columns`; the coefficients' text on the right.
struct FigureLayout {
  int r = 0, n = 0;  // patch resolution, directions
  int cell = 0, side = 0, columns = 0, rows_per_surface = 0, width = 0, height = 0;

  FigureLayout(int resolution, int directions) : r(resolution), n(directions) {
    cell = std::max(3, 160 / r), side = r * cell;
    columns = std::min(kColumns, n + 1);
    rows_per_surface = (n + 1 + columns - 1) / columns;
    width = 2 * kMargin + columns * (side + kMargin) + kText;
    height = kMargin + 2 * rows_per_surface * (side + kLabel + kMargin);
  }
};

// The colour of pixel p of surface s in a panel: 0 the normals, k + 1 channel k scaled by
// mu_max (Sec. 4.2 packing); red where not covered, dimmer outside P.
void panelColour(const PatchImages& im, int s, int panel, float mu_max, int p, double* rgb) {
  const double uncovered[3] = {0.25, 0.05, 0.05};
  const auto pi = static_cast<size_t>(p);
  if (!im.covered[static_cast<size_t>(s)][pi]) {
    std::copy(uncovered, uncovered + 3, rgb);
    return;
  }
  const double dim = im.in_patch[pi] ? 1.0 : 0.5;  // outside P shown dimmer
  if (panel == 0) {
    const Vec3f& m = im.normals[static_cast<size_t>(s)][pi];
    for (int k = 0; k < 3; ++k) rgb[k] = dim * (0.5 + 0.5 * static_cast<double>(m[k]));
    return;
  }
  const auto n = static_cast<size_t>(im.directions);
  const float mu = im.mu[static_cast<size_t>(s)][pi * n + static_cast<size_t>(panel - 1)];
  const double g = dim * std::clamp(static_cast<double>(mu / mu_max), 0.0, 1.0);
  rgb[0] = rgb[1] = rgb[2] = g;
}

// Both surfaces' blocks: normals, then the channels, each labelled.
void drawPanels(cairo_t* cr, const PatchImages& im, const FigureLayout& f, float mu_max) {
  for (int s = 0; s < 2; ++s) {
    const char* name = s == 0 ? "A" : "B";
    for (int panel = 0; panel <= f.n; ++panel) {
      const int row = s * f.rows_per_surface + panel / f.columns;
      const int x = kMargin + (panel % f.columns) * (f.side + kMargin);
      const int y = kMargin + row * (f.side + kLabel + kMargin) + kLabel;
      label(cr, x, y - 5,
            panel == 0 ? std::string("normals ") + name
                       : "mu " + std::string(name) + " d" + std::to_string(panel - 1));
      drawImage(cr, x, y, f.r, f.cell,
                [&](int p, double* rgb) { panelColour(im, s, panel, mu_max, p, rgb); });
    }
  }
}

// The coefficients of Eq. 7 and a legend, as text on the right.
void drawCoefficients(cairo_t* cr, const Contact& c, const FigureLayout& f, float mu_max) {
  const int tx = f.width - kText + kMargin;
  int ty = kMargin + kLabel;
  label(cr, tx, ty,
        "|P| = " + std::to_string(c.covered_pixels) + (c.fallback ? " (fallback)" : ""));
  for (int k = 0; k < f.n; ++k) {
    char line[64];
    std::snprintf(line, sizeof line, "mu_d%d = %.4f", k, static_cast<double>(c.mu.mu[k]));
    label(cr, tx, ty += 16, line);
  }
  label(cr, tx, ty += 24,
        "grey: mu / mu_max (mu_max = " + std::to_string(mu_max).substr(0, 4) + ")");
  label(cr, tx, ty += 16, "red: not covered; dim: outside P");
}

// Both surfaces' blocks (normals, then channels), and the coefficients as text on the right.
void drawFigure(const PatchImages& im, const Contact& c, float mu_max, const std::string& out) {
  const FigureLayout layout(im.resolution, im.directions);
  cairo_surface_t* surface =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 0.12, 0.12, 0.14);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
  drawPanels(cr, im, layout, mu_max);
  drawCoefficients(cr, c, layout, mu_max);
  cairo_destroy(cr);
  // Under a temporary name, renamed once whole (asperity/math/atomic_file.hpp).
  AtomicOutput output(out);
  const cairo_status_t status = cairo_surface_write_to_png(surface, output.temporaryPath().c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw Error("patch: cannot write " + out + ": " + cairo_status_to_string(status));
  }
  output.commit();
}

void runPatch(const PatchOptions& opt) {
  if (opt.out.empty()) throw Error("patch: --out FILE.png is required");
  // The scene after K steps, and contact I of that step.
  const SceneDesc scene = loadScene(opt.scene);
  std::unique_ptr<World> world = instantiate(scene, {frictionProviders()});
  printWarnings(*world);
  for (int k = 0; k < opt.step; ++k) world->step();
  const std::vector<Contact>& contacts = world->contacts();
  if (opt.contact >= static_cast<int>(contacts.size())) {
    throw Error("patch: --contact " + std::to_string(opt.contact) + " does not exist (step " +
                std::to_string(opt.step) + " has " + std::to_string(contacts.size()) +
                " contacts)");
  }
  Contact c = contacts[static_cast<size_t>(opt.contact)];
  CpuPatchSampler sampler;
  PatchImages images;
  const FrictionSettings& settings = world->settings().friction;
  sampler.sampleContact(world->bodies(), c, settings, &images);
  drawFigure(images, c, settings.mu_max, opt.out);
  // The same numbers on stdout.
  std::cout << "contact " << opt.contact << " of " << contacts.size() << " at step " << opt.step
            << ": bodies " << world->body(c.body_a).name << " (A) on " << world->body(c.body_b).name
            << " (B), |P| = " << c.covered_pixels << (c.fallback ? " (fallback to mu0)" : "")
            << "\n";
  for (int k = 0; k < c.mu.count; ++k) std::cout << "mu_d" << k << " = " << c.mu.mu[k] << "\n";
}

}  // namespace

void registerPatchCommand(CLI::App& app) {
  auto opt = std::make_shared<PatchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "patch", "Render one contact's patch (Fig. 7): both surfaces' normals and coefficients");
  cmd->add_option("scene", opt->scene, "scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--step", opt->step, "steps to run before sampling")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--contact", opt->contact, "index of the contact at that step")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--out", opt->out, "output PNG")->required();
  cmd->callback([opt] { runPatch(*opt); });
}

}  // namespace asperity::cli
