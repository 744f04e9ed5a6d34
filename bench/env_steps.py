"""Gymnasium environment throughput: env steps per CPU-second (one core) for the published law
(controller="published", zero actions: the law decides each step) and a random policy, with the
reset cache off (every reset simulates the approach) and on, interleaved in one run.

    PYTHONPATH=build/python_pkg .venv/bin/python bench/env_steps.py [--steps 600] [--rounds 3]

Prints a table of steps per CPU-second (median over rounds) and the ratio on/off. A benchmark:
figures, never pass/fail. CPU seconds of this process, so other load does not count.
"""

import argparse
import statistics
import time

import gymnasium as gym
import numpy as np

import ssc_twin  # noqa: F401  registers the environment


SCENE = None  # --scene: the environment's default when not given


def run(policy, cache, steps, seed):
    kw = dict(controller="published") if policy == "published law" else {}
    if SCENE:
        kw["scene"] = SCENE
    env = gym.make("ssc_twin/EdgeFollowing-v0", reset_cache=cache, **kw)
    rng = np.random.default_rng(seed)
    env.reset(seed=seed)  # the first reset builds the scene (and, with the cache, keeps it)
    done, resets = 0, 0
    t0 = time.process_time()
    while done < steps:
        action = np.zeros(2) if policy == "published law" else rng.uniform(-1, 1, 2)
        _, _, term, trunc, _ = env.step(action)
        done += 1
        if term or trunc:
            env.reset(seed=int(rng.integers(1 << 30)))
            resets += 1
    cpu = time.process_time() - t0
    env.close()
    return steps / cpu, resets


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--steps", type=int, default=600)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--scene", help="a scene name (default: the environment's)")
    args = p.parse_args()
    global SCENE
    SCENE = args.scene
    rows = {}
    for r in range(args.rounds):
        for policy in ("published law", "random policy"):
            for cache in (False, True):
                rate, resets = run(policy, cache, args.steps, seed=100 + r)
                rows.setdefault((policy, cache), []).append((rate, resets))
    print(
        "| policy | reset cache | env steps per CPU-second (median of %d) | resets per run |"
        % args.rounds
    )
    print("| --- | --- | --- | --- |")
    for (policy, cache), v in rows.items():
        print(
            f"| {policy} | {'on' if cache else 'off'} | "
            f"{statistics.median(x[0] for x in v):.0f} | {statistics.median(x[1] for x in v):.0f} |"
        )
    for policy in ("published law", "random policy"):
        on = [x[0] for x in rows[(policy, True)]]
        off = [x[0] for x in rows[(policy, False)]]
        ratios = [a / b for a, b in zip(on, off)]
        print(
            f"{policy}: on/off {statistics.median(ratios):.2f} "
            f"(min {min(ratios):.2f}, max {max(ratios):.2f}, {len(ratios)} pairs)"
        )


if __name__ == "__main__":
    main()
