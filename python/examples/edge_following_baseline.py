"""The baselines of docs/gym.md: the published law and uniform random actions on the
environment, per robot-effects setting. Prints one table row per policy and setting.

    python python/examples/edge_following_baseline.py [--seeds 5] [--scene SCENE]
"""

import argparse
import time

import gymnasium as gym

import ssc_twin  # noqa: F401  registers the environment
from ssc_twin.edge_following import PublishedLawPolicy


def episode(env, policy, seed):
    obs, info = env.reset(seed=seed)
    total, steps = 0.0, 0
    while True:
        obs, reward, terminated, truncated, info = env.step(policy(obs))
        total, steps = total + reward, steps + 1
        if terminated or truncated:
            return info["outcome"], total, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5, help="episodes per row (reset seeds 0..)")
    parser.add_argument("--scene", default=ssc_twin.default_scene())
    args = parser.parse_args()
    print("| policy | effects | seeds | outcomes | return | steps | wall per episode |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for effects in ("default", "off"):
        env = gym.make("ssc_twin/EdgeFollowing-v0", scene=args.scene, effects=effects)
        env.action_space.seed(7)
        policies = {
            "published law (P_ref 100 Pa, β 2, ΔL 7.5 mm)": PublishedLawPolicy(
                env, pref=100, beta=2, step_mm=7.5
            ),
            "uniform random actions (action seed 7)": lambda obs: env.action_space.sample(),
        }
        for name, policy in policies.items():
            start = time.perf_counter()
            runs = [episode(env, policy, seed) for seed in range(args.seeds)]
            wall = (time.perf_counter() - start) / args.seeds
            outcomes = {}
            for outcome, _, _ in runs:
                outcomes[outcome] = outcomes.get(outcome, 0) + 1
            returns = [r for _, r, _ in runs]
            steps = [s for _, _, s in runs]
            print(
                f"| {name} | {effects} | 0–{args.seeds - 1} | "
                + ", ".join(f"{n} {o}" for o, n in sorted(outcomes.items()))
                + f" | {min(returns):.1f} to {max(returns):.1f} | {min(steps)}–{max(steps)} | "
                f"{wall:.2f} s |"
            )
        env.close()


if __name__ == "__main__":
    main()
