"""Train a policy on ssc_twin/EdgeFollowing-v0 in about a minute (docs/gym.md).

    python python/examples/train_edge_following.py [--budget-s 60] [--algo cem|ppo]

cem (the default, NumPy only): the cross-entropy method on a linear policy of the pressure
differentials across the cup and the mean pressure, one episode per candidate. ppo: stable-baselines3's PPO when that
optional library is installed (pip install stable-baselines3). Either prints the trained
policy's outcome and return on five unseen episodes beside the published law's.
"""

import argparse
import sys
import time

import gymnasium as gym
import numpy as np

import ssc_twin  # noqa: F401  registers the environment
from ssc_twin.edge_following import PublishedLawPolicy

ENV_KWARGS = {"effects": "off"}  # the ideal loop: outcomes depend on the policy alone
PRESSURE_SCALE_PA = 100.0  # the mean pressure as log(1 + mean / scale), about 0..7
N_FEATURES = 4


def features(obs):
    """The pressure differentials across the cup normalised by their sum (east-west and
    north-south in the tool frame: P1 SE, P2 NE, P3 NW, P4 SW), the log mean, and a bias."""
    p1, p2, p3, p4 = np.maximum(np.asarray(obs[:4], dtype=np.float64), 0.0)
    total = p1 + p2 + p3 + p4 + 1.0
    return np.array(
        [
            (p1 + p2 - p3 - p4) / total,
            (p2 + p3 - p1 - p4) / total,
            np.log1p(total / 4 / PRESSURE_SCALE_PA),
            1.0,
        ]
    )


class LinearPolicy:
    """action = tanh(W f): W is 2 x N_FEATURES."""

    def __init__(self, weights):
        self.w = np.asarray(weights).reshape(2, N_FEATURES)

    def __call__(self, obs):
        return np.tanh(self.w @ features(obs)).astype(np.float32)


def run_episode(env, policy, seed):
    obs, info = env.reset(seed=seed)
    total = 0.0
    while True:
        obs, reward, terminated, truncated, info = env.step(policy(obs))
        total += reward
        if terminated or truncated:
            return total, info


def train_cem(env, budget_s, rng, population=8, elite=2):
    mean, std = np.zeros(2 * N_FEATURES), np.full(2 * N_FEATURES, 1.0)
    _best, best_return, generation, episodes = mean, -np.inf, 0, 0
    start = time.perf_counter()
    while time.perf_counter() - start < budget_s:
        seed = int(rng.integers(1_000_000))  # every candidate of a generation on one episode
        candidates = mean + std * rng.standard_normal((population, 2 * N_FEATURES))
        returns = np.array([run_episode(env, LinearPolicy(c), seed)[0] for c in candidates])
        episodes += population
        order = np.argsort(returns)[::-1]
        mean = candidates[order[:elite]].mean(axis=0)
        std = np.maximum(candidates[order[:elite]].std(axis=0), 0.05)
        if returns[order[0]] > best_return:
            _best, best_return = candidates[order[0]], returns[order[0]]
        generation += 1
        print(
            f"generation {generation}: best return {returns[order[0]]:.1f}, mean "
            f"{returns.mean():.1f} ({time.perf_counter() - start:.0f} s, {episodes} episodes)",
            file=sys.stderr,
        )
    return LinearPolicy(mean)


def train_ppo(env, budget_s):
    try:
        from stable_baselines3 import PPO
    except ImportError:
        sys.exit("--algo ppo needs stable-baselines3 (pip install stable-baselines3)")
    model = PPO("MlpPolicy", env, n_steps=256, batch_size=64, seed=0, verbose=0)
    start, steps = time.perf_counter(), 0
    while time.perf_counter() - start < budget_s:
        model.learn(total_timesteps=256, reset_num_timesteps=False)
        steps += 256
    print(f"PPO: {steps} steps in {time.perf_counter() - start:.0f} s", file=sys.stderr)
    return lambda obs: model.predict(obs, deterministic=True)[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budget-s", type=float, default=60.0, help="training wall time, s")
    parser.add_argument("--algo", choices=("cem", "ppo"), default="cem")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    env = gym.make("ssc_twin/EdgeFollowing-v0", **ENV_KWARGS)
    rng = np.random.default_rng(args.seed)
    policy = (
        train_cem(env, args.budget_s, rng) if args.algo == "cem" else train_ppo(env, args.budget_s)
    )
    law = PublishedLawPolicy(env)
    for name, p in (("trained", policy), ("published law", law)):
        results = [run_episode(env, p, 10_000 + k) for k in range(5)]
        print(
            f"{name}: returns "
            + " ".join(f"{r:.1f}" for r, _ in results)
            + "; outcomes "
            + " ".join(info["outcome"] for _, info in results)
            + "; progress "
            + " ".join(f"{info['progress_mm']:.0f}" for _, info in results)
            + " mm"
        )


if __name__ == "__main__":
    main()
