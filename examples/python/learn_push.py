"""Learns to push a box to a goal on the sawtooth plate, with the cross-entropy method (CEM)
over one asperity.Batch, and the same learner on a plate of constant friction of the same mean.

The policy is linear in the goal's frame (u from the box toward the goal, n across it): the
finger's force along u and n from the finger's place and velocity and the box's velocity in that
frame. Each CEM iteration runs every candidate on the same few episodes, all candidates side by
side in one batch (asperity.envs.PushOnTextureVec), together with the current mean policy on a
fixed validation set (the learning curve). The learnt policies are then run on 50 held-out
episodes with goals ahead (the sawtooth's easy sense, +x) and behind (its steep sense).

    PYTHONPATH=build/python python3 examples/python/learn_push.py \
        --out docs/images/learn_push.png
"""

import argparse
import time

import numpy as np

from asperity.envs import PushOnTextureVec

# The policy's parameters: weights of the force along u on ALONG, across on ACROSS. The task
# is the same mirrored in y (n, u_y and every lateral quantity change sign), so the force along u
# depends only on what the mirror keeps and the force across on what it flips.
ALONG = ("r_u", "finger v_u", "box v_u", "distance", "u_x", "1")
ACROSS = ("r_n", "finger v_n", "box v_n", "u_y")
PARAMETERS = len(ALONG) + len(ACROSS)
SEEDS = {"train": 0, "validation": 50000, "held_out": 100000}


def features(obs):
    """Features along and across (n, 6), (n, 4) in the goal's frame, and its axes u, n."""
    box, box_v, finger, finger_v, goal = (obs[:, 0:2], obs[:, 4:6], obs[:, 6:8], obs[:, 8:10],
                                          obs[:, 10:12])
    u = goal - box
    distance = np.linalg.norm(u, axis=1)
    u /= np.maximum(distance, 1e-9)[:, None]
    n = np.stack([-u[:, 1], u[:, 0]], axis=1)
    # Places in units of 5 cm, velocities of 0.1 m/s: good gains are of order one.
    r, vf, vb = (finger - box) / 0.05, finger_v / 0.1, box_v / 0.1
    along = np.stack([np.sum(r * u, 1), np.sum(vf * u, 1), np.sum(vb * u, 1), distance / 0.1,
                      u[:, 0], np.ones(len(obs))], axis=1)
    across = np.stack([np.sum(r * n, 1), np.sum(vf * n, 1), np.sum(vb * n, 1), u[:, 1]], axis=1)
    return along, across, u, n


def act(theta, obs):
    """Actions of one policy per world: theta (n, 10) applied to each world's features."""
    along, across, u, n = features(obs)
    a_u = np.sum(theta[:, :len(ALONG)] * along, axis=1)
    a_n = np.sum(theta[:, len(ALONG):] * across, axis=1)
    return np.clip(a_u[:, None] * u + a_n[:, None] * n, -1.0, 1.0)


def rollout(env, theta, seeds):
    """Runs one episode per world (policy theta[i], episode seed seeds[i]) until all ended.
    Returns (success, steps to the goal, final distance over the starting one) per world."""
    obs, info = env.reset(options={"seeds": seeds})
    start = info["distance"].copy()
    ended = np.zeros(env.num_envs, dtype=bool)
    success = np.zeros(env.num_envs, dtype=bool)
    steps = np.full(env.num_envs, env.max_steps)
    final = np.zeros(env.num_envs)
    for s in range(env.max_steps):
        obs, _, terminated, truncated, info = env.step(act(theta, obs))
        new = (terminated | truncated) & ~ended
        success |= new & info["success"]
        steps[new] = s + 1
        final[new] = info["distance"][new]
        ended |= new
        if ended.all():
            break
    return success, steps, final / start


def score(success, steps, remaining, max_steps):
    """Higher is better: any success (2 to 3, by how fast) above any failure (at most 1, by how
    close it got), so that speed never buys a risk of failing."""
    return np.where(success, 3.0 - steps / max_steps, 1.0 - np.minimum(remaining, 2.0))


def learn(texture, args):
    """CEM on one texture. Returns the policy (10 weights) that did best on the validation episodes
    and the curve: (success, mean steps) of each iteration's mean policy there."""
    P, E, V = args.population, args.episodes, args.validation
    env = PushOnTextureVec(P * E + V, texture=texture, autoreset=False, threads=args.threads)
    rng = np.random.default_rng(args.seed)
    mean, std = np.zeros(PARAMETERS), np.full(PARAMETERS, args.std)
    best, best_score, curve = mean, -np.inf, []
    for it in range(args.iterations):
        # Candidates on the same E episodes, then the mean on the validation episodes.
        candidates = mean + std * rng.standard_normal((P, PARAMETERS))
        theta = np.concatenate([np.repeat(candidates, E, axis=0), np.repeat(mean[None], V, 0)])
        seeds = np.concatenate([np.tile(SEEDS["train"] + it * E + np.arange(E), P),
                                SEEDS["validation"] + np.arange(V)])
        success, steps, remaining = rollout(env, theta, seeds)
        scores = score(success, steps, remaining, env.max_steps)
        # The mean as it was, judged on the validation episodes; the best one is kept.
        if scores[P * E:].mean() >= best_score:
            best, best_score = mean, scores[P * E:].mean()
        ok, taken = success[P * E:], steps[P * E:]
        curve.append((ok.mean(), taken[ok].mean() if ok.any() else np.nan))
        # Towards the elites' mean and spread, with a floor that keeps exploring and shrinks.
        fitness = scores[:P * E].reshape(P, E).mean(1)
        elite = candidates[np.argsort(fitness)[-args.elites:]]
        floor = args.min_std * (1.0 - it / args.iterations) + 0.02
        mean = args.smoothing * elite.mean(0) + (1.0 - args.smoothing) * mean
        std = np.maximum(elite.std(0), floor)
        print("%-8s iteration %2d: validation success %3.0f %%, mean steps %5.1f, best "
              "candidate %.2f" % (texture, it + 1, 100 * curve[-1][0], curve[-1][1],
                                  fitness.max()), flush=True)
    return best, curve


def evaluate(texture, policy, directions, episodes, threads):
    """The policy on held-out episodes: (success rate, mean steps of the successes)."""
    env = PushOnTextureVec(episodes, texture=texture, goal_directions=directions,
                           autoreset=False, threads=threads)
    theta = np.repeat(policy[None], episodes, axis=0)
    success, steps, _ = rollout(env, theta, SEEDS["held_out"] + np.arange(episodes))
    return success.mean(), (steps[success].mean() if success.any() else float("nan"))


def plot(curves, path):
    """Learning curves of both textures: validation success and steps to the goal."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.4))
    for texture, curve in curves.items():
        x = np.arange(1, len(curve) + 1)
        label = {"sawtooth": "sawtooth plate", "constant": "constant mu, same mean"}[texture]
        left.plot(x, [100 * c[0] for c in curve], marker="o", label=label)
        right.plot(x, [c[1] for c in curve], marker="o", label=label)
    left.set(xlabel="CEM iteration", ylabel="validation success (%)", ylim=(-5, 105))
    right.set(xlabel="CEM iteration", ylabel="steps of 20 ms to the goal (successes)")
    left.legend(loc="lower right")
    for ax in (left, right):
        ax.grid(alpha=0.3)
    fig.suptitle("Pushing a box to goals ahead (+x) with the cross-entropy method")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--iterations", type=int, default=25)
    p.add_argument("--population", type=int, default=48)
    p.add_argument("--elites", type=int, default=8)
    p.add_argument("--episodes", type=int, default=8, help="training episodes per candidate")
    p.add_argument("--validation", type=int, default=24,
                   help="episodes of the curve and of the choice of the policy")
    p.add_argument("--held-out", type=int, default=50)
    p.add_argument("--std", type=float, default=1.5)
    p.add_argument("--min-std", type=float, default=0.5,
                   help="floor of the spread at the start, shrinking to 0.02 at the end")
    p.add_argument("--smoothing", type=float, default=0.8,
                   help="weight of the elites' mean in the new mean")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--textures", nargs="+", default=["sawtooth", "constant"],
                   choices=["sawtooth", "constant"])
    p.add_argument("--out", default="learn_push.png")
    args = p.parse_args()
    start = time.perf_counter()
    policies, curves = {}, {}
    for texture in args.textures:
        policies[texture], curves[texture] = learn(texture, args)
    print("\nheld-out episodes (%d each): success, mean steps of 20 ms to the goal"
          % args.held_out)
    for directions in ("ahead", "behind"):
        for texture in args.textures:
            ok, steps = evaluate(texture, policies[texture], directions, args.held_out,
                                 args.threads)
            print("  %-8s goals %-6s: success %3.0f %%, mean steps %5.1f"
                  % (texture, directions, 100 * ok, steps))
    plot(curves, args.out)
    print("\ncurves in %s; %.1f s in all" % (args.out, time.perf_counter() - start))


if __name__ == "__main__":
    main()
