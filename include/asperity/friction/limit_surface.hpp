// Limit surfaces (SPEC 4): the set of admissible tangential impulses (lambda_t, lambda_b) on A
// for a given normal impulse lambda_n >= 0. Each is a small value type in its own header under
// limit_surfaces/, with its construction from a contact's coefficients (`fromContact`) and its
// projection (`project`), which the PGS solver calls in every iteration, so they are cheap,
// inline where they can be, and allocation-free.
//
// Convention (SPEC 1): mu_d bounds the friction on A along d: f.d <= mu_d lambda_n.
// Every projection returns (0, 0) for lambda_n <= 0 (or NaN) and treats negative
// coefficients as 0. None allocates; a point already inside is returned unchanged.
//
// Adding a surface (docs/step.md): a header in limit_surfaces/ with the struct, one enum value
// and name below, and the type in LimitSurfaceTypes at the enum value's position.
#pragma once

#include <tuple>

#include "asperity/friction/limit_surfaces/box_limit.hpp"
#include "asperity/friction/limit_surfaces/coulomb_limit.hpp"
#include "asperity/friction/limit_surfaces/polygon_limit.hpp"
#include "asperity/math/enum_names.hpp"

namespace asperity {

enum class LimitSurfaceKind { Coulomb, Box, Polygon };
inline constexpr std::pair<const char*, LimitSurfaceKind> kLimitSurfaceNames[] = {
    {"coulomb", LimitSurfaceKind::Coulomb},
    {"box", LimitSurfaceKind::Box},
    {"polygon", LimitSurfaceKind::Polygon}};

// The surface types in enum order: the solver picks std::tuple_element<kind> (the one dispatch).
using LimitSurfaceTypes = std::tuple<CoulombLimit, BoxLimit, PolygonLimit>;
static_assert(std::tuple_size_v<LimitSurfaceTypes> == std::size(kLimitSurfaceNames),
              "every limit surface has a type and a name");

}  // namespace asperity
