// MuJoCo geoms as ContactFriction objects: which geoms Asperity can shape, which carry a
// surface, the checks the model must pass, and each geom's pose and velocity per step.
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <string>
#include <vector>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/engines/engine_surfaces.hpp"

namespace asperity::mujoco_detail {

struct GeomObjects {
  std::vector<ObjectId> object;   // per geom; kNoObject where Asperity has no such shape
  std::vector<uint8_t> textured;  // per geom: 1 when the surfaces file names it
};

// The geom's name, or "geom <id>" when it has none.
std::string geomName(const mjModel* m, int geom);

// Registers every geom Asperity can shape (textured ones with their surface, the others flat).
// Throws asperity::Error for a surface whose geom the model lacks (naming the file and the
// name), a textured geom with condim 1 or of a type Asperity lacks, or an explicit contact pair
// of condim 1 with a textured geom.
GeomObjects registerGeoms(const mjModel* m, const EngineSurfaces& surfaces,
                          ContactFriction& friction);

// The overlap (m, >= 0) of a contact. MuJoCo 2.2's box-box collider reports half of it in
// `dist` (its point is the true midpoint); the patch's depth clip (SPEC 3) needs all of it.
double contactDepth(const mjModel* m, const mjContact& c);

// Where the geom is and how it moves (needs mj_kinematics, mj_comPos and mj_comVel).
ObjectState geomState(const mjModel* m, const mjData* d, int geom);

// The adapter repeats mj_fwdPosition's calls in MuJoCo 2.2's order (mujoco_friction.cpp): throws
// asperity::Error naming both versions unless `library` (mj_version()) is a 2.2 release and the
// one of the headers it was built with (mjVERSION_HEADER).
void checkMujocoVersion(int library, int header, const std::string& library_text);

}  // namespace asperity::mujoco_detail
