"""Environments for learning on textured friction, Gymnasium-style without Gymnasium.

PushOnTextureVec(n) steps n episodes at once on an asperity.Batch; PushOnTexture is one episode
with Gymnasium's single-environment interface. A force-driven finger (a sphere held at a fixed
height) pushes a 10 cm box to a goal on a textured plate: sawtooth (its ramps let the box slide
along +x and its steep faces hold it against -x), anisotropic Gaussian, or concrete, drawn per
episode; or a plate of constant friction for comparison. docs/python.md describes the task.
"""

import math

import numpy as np

from . import Batch, cone, generate_texture
from .spaces import Box

try:  # Gymnasium's base class where it is installed, so that its wrappers accept the env.
    from gymnasium import Env as _EnvBase
except ImportError:
    _EnvBase = object

TEXTURES = ("sawtooth", "gaussian", "concrete")
MU0 = 0.2
# The plates' surfaces (docs/textures.md): gain 2 as the paper's materials.
SURFACES = {
    "sawtooth": {"normal_map": {"generator": "sawtooth", "params": {"period": 16}, "size": 128},
                 "gain": 2, "texture_size": 0.08},
    "gaussian": {"normal_map": {"generator": "gaussian", "params": {"sx": 0.25, "sy": 1},
                                "size": 128}, "gain": 2, "texture_size": 0.08},
    "concrete": {"normal_map": {"generator": "concrete", "size": 256}, "gain": 2,
                 "texture_size": 0.256},
}
LANE_SPACING = 3.0    # m between the plates' centres along y (one plate per texture)
PLATE_HALF = 0.75     # m, half the side of a plate
BOX_HALF = 0.05       # m, half the side of the box (1 kg)
FINGER_RADIUS = 0.03  # m
FINGER_HEIGHT = 0.04  # m, the finger's centre above the plate (1 cm clear of it)
FINGER_MASS = 1.0     # kg
FINGER_DAMPING = 20.0  # N s/m, viscous drag on the finger in the plane
HOVER_STIFFNESS, HOVER_DAMPING = 100.0, 15.0  # N/m, N s/m: the height controller
GOAL_RADIUS = 0.05    # m: the episode succeeds when the box centre is this close
# Goal directions from the box, as angle ranges (rad from +x).
GOAL_DIRECTIONS = {"ahead": (-math.pi / 4, math.pi / 4),
                   "behind": (3 * math.pi / 4, 5 * math.pi / 4),
                   "any": (0.0, 2 * math.pi)}
OBS_NAMES = ("box_x", "box_y", "box_cos_yaw", "box_sin_yaw", "box_vx", "box_vy", "finger_x",
             "finger_y", "finger_vx", "finger_vy", "goal_x", "goal_y")


def mean_mu(texture="sawtooth"):
    """The mean of a plate's four box bounds mu_{+t}, mu_{+b}, mu_{-t}, mu_{-b} (Eq. 7 on the
    whole texture, a flat box), the constant mu of the same mean."""
    s = SURFACES[texture]
    spec = s["normal_map"]
    m = generate_texture(spec["generator"], size=spec["size"], **spec.get("params", {}))
    return float(np.mean(list(cone(m, k_b=s["gain"], mu0=MU0)["box"].values())))


def push_scene(textures=TEXTURES, constant_mu=None):
    """The scene: one plate per texture, lane k centred at y = k LANE_SPACING, then the box and
    the finger. With constant_mu, one plate of that constant friction (and every contact too)."""
    plates = []
    for k, name in enumerate(textures):
        shape = {"type": "box", "half_extents": [PLATE_HALF, PLATE_HALF, 0.05]}
        if constant_mu is None:
            shape["surface"] = SURFACES[name]
        plates.append({"name": "plate_" + name, "type": "static",
                       "position": [0, k * LANE_SPACING, -0.05], "shapes": [shape]})
    settings = {"dt": 0.01, "mu0": MU0, "friction_provider": "cone"}
    if constant_mu is not None:
        settings.update(mu0=float(constant_mu), friction_provider="constant")
    box = {"name": "box", "position": [0, 0, BOX_HALF],
           "shapes": [{"type": "box", "half_extents": [BOX_HALF] * 3}]}
    finger = {"name": "finger", "position": [0, -0.2, FINGER_HEIGHT], "mass": FINGER_MASS,
              "shapes": [{"type": "sphere", "radius": FINGER_RADIUS}]}
    return {"settings": settings, "bodies": plates + [box, finger]}


def _spaces(n):
    """Observation and action boxes of one environment and of n."""
    high = np.array([1.0, 1.0, 1.0, 1.0, 5.0, 5.0, 1.5, 1.5, 5.0, 5.0, 1.0, 1.0])
    single_obs = Box(-high, high, dtype=np.float64)
    single_act = Box(-1.0, 1.0, shape=(2,), dtype=np.float64)
    obs = Box(np.tile(-high, (n, 1)), np.tile(high, (n, 1)), dtype=np.float64)
    act = Box(-1.0, 1.0, shape=(n, 2), dtype=np.float64)
    return single_obs, single_act, obs, act


class PushOnTextureVec:
    """n pushing episodes stepped together on one asperity.Batch (Gymnasium's vector interface).

    texture: 'random' (drawn per episode among TEXTURES), one of TEXTURES, or 'constant' (a
    plate of constant friction, constant_mu, default the sawtooth's mean_mu()). goal_directions:
    'ahead' (within 45 degrees of +x, the sawtooth's easy sense), 'behind' or 'any'. An action
    is the finger's planar force over max_force, in [-1, 1]^2; it holds for frame_skip steps
    of 10 ms. Episodes end on success (terminated), a box off the plate or tipped over
    (terminated), or after max_steps (truncated). With autoreset, an ended episode restarts at
    the next step() call, which ignores its action and returns its first observation with reward
    0 (Gymnasium's next-step autoreset).
    """

    metadata = {"render_modes": [], "autoreset_mode": "NextStep"}

    def __init__(self, num_envs, texture="random", goal_directions="ahead", frame_skip=2,
                 max_steps=250, max_force=10.0, threads=0, autoreset=True, constant_mu=None):
        if texture not in TEXTURES + ("random", "constant"):
            raise ValueError("texture must be 'random', 'constant' or one of %s, got %r"
                             % (", ".join(TEXTURES), texture))
        if goal_directions not in GOAL_DIRECTIONS:
            raise ValueError("goal_directions must be one of %s, got %r"
                             % (", ".join(GOAL_DIRECTIONS), goal_directions))
        if int(frame_skip) < 1 or int(max_steps) < 1 or not max_force > 0:
            raise ValueError("frame_skip and max_steps must be >= 1 and max_force > 0")
        self.num_envs, self.texture, self.autoreset = int(num_envs), texture, autoreset
        self.frame_skip, self.max_steps, self.max_force = int(frame_skip), int(max_steps), max_force
        self.goal_directions = goal_directions
        self.lanes = TEXTURES if texture == "random" else (texture,)
        self.constant_mu = None
        if texture == "constant":
            self.constant_mu = mean_mu("sawtooth") if constant_mu is None else float(constant_mu)
        self.batch = Batch(push_scene(self.lanes, self.constant_mu), self.num_envs,
                           threads=threads)
        self._box, self._finger = len(self.lanes), len(self.lanes) + 1
        self._initial = {"positions": self.batch.positions.copy(),
                         "orientations": self.batch.orientations.copy()}
        (self.single_observation_space, self.single_action_space,
         self.observation_space, self.action_space) = _spaces(self.num_envs)
        n = self.num_envs
        self._rngs = [np.random.default_rng() for _ in range(n)]
        self._lane = np.zeros(n, dtype=np.int64)
        self._goal = np.zeros((n, 2))
        self._steps = np.zeros(n, dtype=np.int64)
        self._distance = np.zeros(n)
        self._needs_reset = np.zeros(n, dtype=bool)

    def reset(self, seed=None, options=None):
        """Starts every episode. seed: episode i draws from seed + i; options={'seeds': (n,)}
        gives each its own seed. Returns (obs (n, 12), info)."""
        seeds = (options or {}).get("seeds")
        if seeds is not None:
            seeds = np.asarray(seeds, dtype=np.int64).reshape(-1)
            if seeds.shape != (self.num_envs,):
                raise ValueError("options['seeds'] must have shape (%d,)" % self.num_envs)
        elif seed is not None:
            seeds = int(seed) + np.arange(self.num_envs)
        if seeds is not None:
            self._rngs = [np.random.default_rng(int(s)) for s in seeds]
        self._start(np.ones(self.num_envs, dtype=bool))
        obs = self._observe()
        return obs, self._info(np.zeros(self.num_envs, dtype=bool))

    def step(self, actions):
        """Applies the (n, 2) actions for frame_skip steps. Returns (obs, reward, terminated,
        truncated, info), each with n rows."""
        a = np.asarray(actions, dtype=np.float64)
        if a.shape != (self.num_envs, 2):
            raise ValueError("actions must have shape (%d, 2), got %s" % (self.num_envs, a.shape))
        if not np.all(np.isfinite(a)):
            raise ValueError("actions must be finite")
        restart = self._needs_reset.copy()
        a = np.where(restart[:, None], 0.0, np.clip(a, -1.0, 1.0))
        # The finger's force: the action, drag, and the height controller against gravity.
        self.batch.set_force("finger", self._finger_force(a))
        self.batch.step(self.frame_skip)
        self._steps += 1
        before = self._distance.copy()
        obs = self._observe()
        success = self._distance < GOAL_RADIUS
        terminated = success | self._failed()
        truncated = (self._steps >= self.max_steps) & ~terminated
        reward = 10.0 * (before - self._distance) - 0.01 * np.sum(a * a, axis=1) + 5.0 * success
        # Episodes that ended last call start again now (their step above went unused).
        if restart.any():
            self._start(restart)
            obs = self._observe()
            reward[restart], terminated[restart], truncated[restart] = 0.0, False, False
            success[restart] = False
        if self.autoreset:
            self._needs_reset = terminated | truncated
        return obs, reward, terminated, truncated, self._info(success)

    def close(self):
        """Nothing to release (the batch goes with the environment)."""

    def _finger_force(self, a):
        """(n, 3) forces on the finger for actions a (n, 2)."""
        v = self.batch.linear_velocities[:, self._finger]
        z = self.batch.positions[:, self._finger, 2]
        f = np.empty((self.num_envs, 3))
        f[:, :2] = self.max_force * a - FINGER_DAMPING * v[:, :2]
        f[:, 2] = (FINGER_MASS * 9.81 + HOVER_STIFFNESS * (FINGER_HEIGHT - z)
                   - HOVER_DAMPING * v[:, 2])
        return f

    def _start(self, mask):
        """Draws the episodes of the masked worlds and puts their worlds there, new."""
        positions = self._initial["positions"].copy()
        orientations = self._initial["orientations"].copy()
        for i in np.flatnonzero(mask):
            lane, box, yaw, finger, goal = self._draw(self._rngs[i])
            offset = np.array([0.0, lane * LANE_SPACING])
            positions[i, self._box] = [*(box + offset), BOX_HALF]
            positions[i, self._finger] = [*(finger + offset), FINGER_HEIGHT]
            orientations[i, self._box] = [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]
            self._lane[i], self._goal[i] = lane, goal
        self.batch.reset(mask, state={"positions": positions, "orientations": orientations})
        self._steps[mask] = 0
        self._needs_reset[mask] = False

    def _draw(self, rng):
        """One episode: lane, box position and yaw, finger position, goal (plate coordinates)."""
        lane = int(rng.integers(len(self.lanes)))
        box = rng.uniform(-0.05, 0.05, size=2)
        yaw = rng.uniform(-0.3, 0.3)
        low, high = GOAL_DIRECTIONS[self.goal_directions]
        angle, distance = rng.uniform(low, high), rng.uniform(0.25, 0.4)
        goal = box + distance * np.array([math.cos(angle), math.sin(angle)])
        # The finger starts behind the box as seen from the goal, a little to one side.
        along = np.array([math.cos(angle), math.sin(angle)])
        side = rng.uniform(-0.03, 0.03) * np.array([-along[1], along[0]])
        finger = box - rng.uniform(0.1, 0.14) * along + side
        return lane, box, yaw, finger, goal

    def _observe(self):
        """(n, 12) observations in plate coordinates; updates the distances to the goals."""
        p, v = self.batch.positions, self.batch.linear_velocities
        q = self.batch.orientations[:, self._box]
        offset = np.stack([np.zeros(self.num_envs), self._lane * LANE_SPACING], axis=1)
        box, finger = p[:, self._box, :2] - offset, p[:, self._finger, :2] - offset
        yaw = np.arctan2(2 * (q[:, 0] * q[:, 3] + q[:, 1] * q[:, 2]),
                         1 - 2 * (q[:, 2] ** 2 + q[:, 3] ** 2))
        self._distance = np.linalg.norm(box - self._goal, axis=1)
        obs = np.concatenate([box, np.cos(yaw)[:, None], np.sin(yaw)[:, None],
                              v[:, self._box, :2], finger, v[:, self._finger, :2], self._goal],
                             axis=1)
        space = self.single_observation_space
        return np.clip(obs, space.low, space.high)

    def _failed(self):
        """Boxes off their plate, fallen, or tipped by more than 30 degrees."""
        p = self.batch.positions[:, self._box]
        q = self.batch.orientations[:, self._box]
        up = 1 - 2 * (q[:, 1] ** 2 + q[:, 2] ** 2)  # z of the box's z axis
        off = np.abs(p[:, 0]) > PLATE_HALF
        off |= np.abs(p[:, 1] - self._lane * LANE_SPACING) > PLATE_HALF
        return off | (p[:, 2] < 0.5 * BOX_HALF) | (up < math.cos(math.radians(30)))

    def _info(self, success):
        names = np.array(["constant" if self.texture == "constant" else t for t in self.lanes])
        return {"success": success, "distance": self._distance.copy(),
                "texture": names[self._lane], "steps": self._steps.copy()}


class PushOnTexture(_EnvBase):
    """One pushing episode (Gymnasium's Env interface): PushOnTextureVec with n = 1 and no
    autoreset. reset(seed) gives the episode that world 0 of PushOnTextureVec.reset(seed) gives.
    """

    metadata = {"render_modes": []}
    render_mode = None

    def __init__(self, texture="random", goal_directions="ahead", frame_skip=2, max_steps=250,
                 max_force=10.0, constant_mu=None):
        self._vec = PushOnTextureVec(1, texture=texture, goal_directions=goal_directions,
                                     frame_skip=frame_skip, max_steps=max_steps,
                                     max_force=max_force, threads=1, autoreset=False,
                                     constant_mu=constant_mu)
        self.observation_space = self._vec.single_observation_space
        self.action_space = self._vec.single_action_space

    @property
    def batch(self):
        """The asperity.Batch of one world underneath."""
        return self._vec.batch

    def reset(self, *, seed=None, options=None):
        """Starts an episode; returns (obs (12,), info)."""
        obs, info = self._vec.reset(seed=seed)
        return obs[0], {k: v[0] for k, v in info.items()}

    def step(self, action):
        """Applies a (2,) action; returns (obs, reward, terminated, truncated, info)."""
        action = np.asarray(action, dtype=np.float64)
        if action.shape != (2,):
            raise ValueError("action must have shape (2,), got %s" % (action.shape,))
        obs, reward, terminated, truncated, info = self._vec.step(action[None])
        return (obs[0], float(reward[0]), bool(terminated[0]), bool(truncated[0]),
                {k: v[0] for k, v in info.items()})

    def close(self):
        """Nothing to release."""
