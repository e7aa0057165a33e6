// A renderer-agnostic draw list of what the step saw (no OpenGL here): contact points, contact
// frames (t, b, n), patch squares of width w, and each contact's friction limit polygon scaled
// by its normal force. The renderer, the viewer and plots draw it as they like.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/math/types.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

class World;

struct DebugLine {
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
  Vec3 color = Vec3::Ones();  // linear RGB in [0, 1]
};

struct DebugPoint {
  Vec3 position = Vec3::Zero();
  Vec3 color = Vec3::Ones();
  float size = 8.0f;  // pixels
};

// A closed planar loop (drawn as its outline; filled when `filled`, as a fan from vertex 0).
struct DebugPolygon {
  std::vector<Vec3> loop;
  Vec3 color = Vec3::Ones();
  bool filled = false;
};

struct DebugDrawList {
  std::vector<DebugLine> lines;
  std::vector<DebugPoint> points;
  std::vector<DebugPolygon> polygons;

  void clear();
  bool empty() const { return lines.empty() && points.empty() && polygons.empty(); }
};

// Which layers to draw (bit set).
enum DebugLayer : uint32_t {
  kLayerContacts = 1u << 0,  // contact points
  kLayerFrames = 1u << 1,    // t (red), b (green), n (blue) at each contact
  kLayerCones = 1u << 2,     // friction limit polygon through mu_{d_k} d_k * force
  kLayerPatches = 1u << 3,   // the w x w patch square in the (t, b) plane
};

// Parses "contacts,frames,cones,patches" (any subset, comma separated; "none" or "" = 0).
// Throws asperity::Error naming an unknown layer.
uint32_t parseDebugLayers(const std::string& list);

struct DebugDrawOptions {
  uint32_t layers = kLayerContacts;
  double frame_length = 0.05;  // m, length of the t, b, n axes
  double cone_scale = 0.005;   // m per N: polygon radius = mu_d * (lambda_n / dt) * scale
  double patch_width = 0.02;   // m (w), usually FrictionSettings::patch_width
  Vec3 contact_color = Vec3(1.0, 0.85, 0.1);
  Vec3 fallback_color = Vec3(1.0, 0.1, 0.6);  // contacts whose patch was empty (mu = mu0)
  Vec3 patch_color = Vec3(0.1, 0.9, 1.0);
};

// Colour of an in-plane direction (angle from t toward b, radians): a hue wheel, so the cone's
// d_k edges read as "which way" at a glance (t red, b yellow-green, -t cyan, -b violet).
Vec3 directionColor(double angle);

// Appends the chosen layers for these contacts. dt (s) turns normal impulses into forces.
void appendContactLayers(std::span<const Contact> contacts, double dt,
                         const DebugDrawOptions& options, DebugDrawList& out);

// Same for a world's last step (patch width from its friction settings when options' is 0).
void appendWorldLayers(const World& world, const DebugDrawOptions& options, DebugDrawList& out);

}  // namespace asperity
