// Boxes on four materials (Sec. 5.1, Fig. 9): equal boxes launched with equal velocity; the
// rougher the plane, the shorter the slide.
#include <cmath>

#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kBoxesRow = paperRow(2, 2, 0.2, 0.02, 10, 16, 3.1, 0.5, 2.3);

// Boxes on four materials (Sec. 5.1, Fig. 9): equal boxes, equal start velocity.
Outcome evaluateBoxes(const Experiment& e, const RunOptions& options) {
  const SceneRun& run = e.scenes.at(0);
  const std::vector<std::string> names = {"concrete", "cast_iron", "steel", "plastic"};
  std::vector<std::string> bodies;
  for (const std::string& n : names) bodies.push_back("box_" + n);
  Recording rec = simulate(run.file, run.seconds, options, bodies);
  Outcome out;
  out.profiles.push_back(rec.profile);
  // Slide distance of each box; the plot shows it over time.
  Plot plot{"Slide distance of the boxes", "time (s)", "distance (m)", {}};
  std::vector<double> d;
  for (size_t i = 0; i < names.size(); ++i) {
    const auto& p = rec.of(bodies[i]);
    d.push_back(horizontalTravel(p));
    out.measures.push_back({"slide_" + names[i], d.back(), "m"});
    plot.series.push_back(makeSeries(names[i], rec.time, [&](size_t k) {
      return std::hypot(p[k].position.x() - p[0].position.x(),
                        p[k].position.y() - p[0].position.y());
    }));
  }
  out.plots.push_back(plot);
  // concrete < cast iron < steel <= plastic.
  const bool a = d[0] < d[1], b = d[1] < d[2], c = d[2] <= d[3];
  out.passed = a && b && c;
  out.explanation = "slide concrete " + num(d[0]) + " m" + relation(a, "<") + "cast iron " +
                    num(d[1]) + " m" + relation(b, "<") + "steel " + num(d[2]) + " m" +
                    relation(c, "<=") + "plastic " + num(d[3]) + " m";
  return out;
}

}  // namespace

Experiment boxesOnMaterials() {
  return {"boxes_on_materials",
          "Boxes on four materials",
          "Sec. 5.1, Fig. 9: equal boxes launched with equal velocity on concrete "
          "(Ra 1 mm), cast iron (0.15 mm), steel (0.01 mm) and smooth plastic (0); the "
          "rougher the plane, the shorter the slide.",
          "slide distances concrete < cast iron < steel <= plastic",
          {{"boxes_on_materials.json", 2.0, kBoxesRow}},
          evaluateBoxes};
}

}  // namespace asperity::experiments
