/* Asperity's contact friction for C and foreign-function interfaces (docs/engines.md): the C
 * face of asperity/engines/contact_friction.hpp. Every call returns an asperity_status; on
 * anything but ASPERITY_OK, asperity_friction_error(handle) holds a message naming what is
 * wrong (valid until the next call on that handle). No global state: each handle is
 * independent, and one handle may be used by one thread at a time.
 *
 * Conventions (SPEC 1): object A first, the normal points from B toward A, depth >= 0 is the
 * penetration; mu_d bounds the friction force on A along d. Units: metres, seconds, radians.
 * Quaternions are (w, x, y, z). */
#ifndef ASPERITY_C_CONTACT_FRICTION_H
#define ASPERITY_C_CONTACT_FRICTION_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum asperity_status {
  ASPERITY_OK = 0,
  ASPERITY_ERROR_INVALID_ARGUMENT = 1, /* a bad value, name, id or index */
  ASPERITY_ERROR_NOT_FOUND = 2,        /* a file that cannot be read */
  ASPERITY_ERROR_FAILED = 3            /* anything else (the message says what) */
} asperity_status;

typedef enum asperity_frame_mode {
  ASPERITY_FRAME_WORLD = 0,
  ASPERITY_FRAME_BODY = 1,
  ASPERITY_FRAME_AUTO = 2,
  ASPERITY_FRAME_TEXTURE = 3
} asperity_frame_mode;

typedef enum asperity_shape_type {
  ASPERITY_SHAPE_BOX = 0,
  ASPERITY_SHAPE_SPHERE = 1,
  ASPERITY_SHAPE_CAPSULE = 2,
  ASPERITY_SHAPE_CYLINDER = 3,
  ASPERITY_SHAPE_PLANE = 4,
  ASPERITY_SHAPE_MESH = 6
} asperity_shape_type;

typedef struct asperity_friction asperity_friction; /* opaque */

typedef struct asperity_friction_settings {
  int directions;         /* N, 4..64 */
  double mu0;             /* nominal coefficient */
  double patch_width;     /* w (m) */
  int patch_resolution;   /* R */
  double reuse_pixels;    /* patch coherence tolerance; 0 = sample every call */
  const char* provider;   /* "cpu", "cone" or "constant" */
  int frame_mode;         /* asperity_frame_mode */
  double world_axis[3];
  int threads;            /* 0 = every core, 1 = the calling thread */
} asperity_friction_settings;

/* One shape of an object, in the object's frame, with the surface mapped on it. */
typedef struct asperity_shape {
  int type;                 /* asperity_shape_type */
  double position[3];       /* shape frame in the object frame */
  double rotation[4];       /* (w, x, y, z) */
  double half_extents[3];   /* box */
  double radius;            /* sphere, capsule, cylinder */
  double half_height;       /* capsule, cylinder (along local z) */
  double plane_normal[3];   /* plane: {x : n.x = offset} */
  double plane_offset;
  /* mesh: vertex positions (3 per vertex), UVs (2 per vertex, or NULL) and triangles */
  const double* vertices;
  const double* uvs;
  size_t vertex_count;
  const int32_t* triangles; /* 3 per triangle */
  size_t triangle_count;
  /* surface: a PNG normal map path or a generator "gen:NAME[:SEED]" (NULL: flat) */
  const char* normal_map;
  double gain;              /* k of Eq. 7 */
  double texture_size;      /* m per texture repeat */
  double texture_rotation;  /* rad */
} asperity_shape;

typedef struct asperity_contact {
  uint32_t object_a, object_b;
  int32_t shape_a, shape_b;
  double point[3];
  double normal[3]; /* unit, from B toward A */
  double depth;     /* >= 0 */
  uint64_t key;     /* persistent id, 0 = none */
} asperity_contact;

typedef struct asperity_contact_friction {
  double t[3], b[3];   /* frame, b = n x t */
  float mu[64];        /* mu_d, d_k = cos(2 pi k/N) t + sin(2 pi k/N) b; N entries used */
  int directions;
  double bounds[4];    /* +t, +b, -t, -b */
  double symmetric[2]; /* the coefficient per axis (t, b) for a symmetric cone */
  int fallback;        /* the patch was empty: mu = mu0 */
} asperity_contact_friction;

/* Defaults: N 4, mu0 0.2, w 0.02 m, R 16, reuse 0.1, "cpu", world frame along x, 1 thread. */
void asperity_friction_default_settings(asperity_friction_settings* settings);
void asperity_friction_default_shape(asperity_shape* shape);

/* Creates a handle. On failure *out is still a handle, holding the message: read it with
 * asperity_friction_error and free it with asperity_friction_destroy. */
asperity_status asperity_friction_create(const asperity_friction_settings* settings,
                                         asperity_friction** out);
void asperity_friction_destroy(asperity_friction* handle);
const char* asperity_friction_error(const asperity_friction* handle);
/* The warnings found while surfaces were loaded (a normal map with texels that are not
 * normals...), one per line; "" when none. Valid until the next call on the handle. */
const char* asperity_friction_warnings(asperity_friction* handle);

asperity_status asperity_friction_add_object(asperity_friction* handle, const char* name,
                                             const asperity_shape* shapes, size_t shape_count,
                                             uint32_t* id);
/* Pose (position, quaternion w x y z) and velocities of the object's frame this step. */
asperity_status asperity_friction_set_state(asperity_friction* handle, uint32_t id,
                                            const double position[3],
                                            const double rotation[4],
                                            const double linear_velocity[3],
                                            const double angular_velocity[3]);
/* Fills out[i] for contacts[i]. */
asperity_status asperity_friction_compute(asperity_friction* handle,
                                          const asperity_contact* contacts, size_t count,
                                          asperity_contact_friction* out);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_C_CONTACT_FRICTION_H */
