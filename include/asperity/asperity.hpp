// Everything a program needs to build worlds, load scenes and read friction from textures:
// one include for the core library (target asperity::asperity). The OpenGL patch sampler
// (asperity/sampler/gl_patch_sampler.hpp, target asperity::gl;
// asperity/scene/gl_sampler_provider.hpp offers it to scenes as "gl") and the renderer
// (asperity/render/*.hpp, target asperity::render) have their own headers and targets.
#pragma once

#include "asperity/diagnostics.hpp"
#include "asperity/error.hpp"
#include "asperity/math/types.hpp"

// Bodies, shapes and what their surfaces look like.
#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/driver.hpp"
#include "asperity/dynamics/joint.hpp"
#include "asperity/geometry/asset_import.hpp"
#include "asperity/geometry/mesh_io.hpp"
#include "asperity/geometry/shape.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "asperity/geometry/surface.hpp"

// Normal maps: generated, read, inspected.
#include "asperity/texture/generators.hpp"
#include "asperity/texture/map_inspect.hpp"
#include "asperity/texture/normal_map.hpp"
#include "asperity/texture/png_io.hpp"

// The friction model and the samplers that turn two surfaces into coefficients.
#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/sampler/friction_provider.hpp"

// The world, its step, its contacts and its profile; scenes, ensembles of runs and batches.
#include "asperity/batch/batch.hpp"
#include "asperity/collision/contact.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/sweep/sweep.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/debug_draw.hpp"
#include "asperity/world/run_loop.hpp"
#include "asperity/world/state_check.hpp"
#include "asperity/world/world.hpp"

// Measuring friction: the virtual tribometer.
#include "asperity/tribometer/tribometer.hpp"
