"""The environment's reset cache: episodes started from the kept approach are the episodes a
reset from scratch gives (observations, rewards and outcomes equal to the bit) for the same
seeds, with the law and with a random policy, and the cache is used. And the environment on a
machine without a display, as docs/gym.md says: check_env passes, rgb_array renders, a fault's
reason is in info, objects() takes a list, and nothing is printed about leaks at exit."""

import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

import numpy as np

try:
    import gymnasium as gym
except ImportError:
    gym = None

import ssc_twin  # noqa: F401  registers the environment


@unittest.skipIf(gym is None, "gymnasium not installed")
class ResetCacheTest(unittest.TestCase):
    def episodes(self, cache, policy, seeds, steps=40):
        kw = dict(controller="published") if policy == "law" else {}
        env = gym.make(
            "ssc_twin/EdgeFollowing-v0", scene="disk_benchmark_fast", reset_cache=cache, **kw
        )
        rng = np.random.default_rng(7)
        out = []
        for seed in seeds:
            obs, _ = env.reset(seed=seed)
            trace = [obs.copy()]
            for _ in range(steps):
                a = np.zeros(2) if policy == "law" else rng.uniform(-1, 1, 2)
                obs, r, term, trunc, info = env.step(a)
                trace.append((obs.copy(), r, info["outcome"]))
                if term or trunc:
                    break
            out.append(trace)
        used = env.unwrapped._trials[None].resets_from_cache
        env.close()
        return out, used

    def test_a_cached_reset_gives_the_episode_of_a_reset_from_scratch(self):
        for policy in ("law", "random"):
            with self.subTest(policy=policy):
                seeds = [3, 11, 3]
                scratch, none_used = self.episodes(False, policy, seeds)
                cached, used = self.episodes(True, policy, seeds)
                self.assertEqual(none_used, 0)
                self.assertEqual(used, len(seeds) - 1)  # the first reset simulates it
                self.assertEqual(len(scratch), len(cached))
                for a, b in zip(scratch, cached):
                    self.assertEqual(len(a), len(b))
                    np.testing.assert_array_equal(a[0], b[0])
                    for x, y in zip(a[1:], b[1:]):
                        np.testing.assert_array_equal(x[0], y[0])
                        self.assertEqual(x[1:], y[1:])


@unittest.skipIf(gym is None, "gymnasium not installed")
class HeadlessTest(unittest.TestCase):
    def test_without_a_display_as_the_docs_say(self):
        out = tempfile.mkdtemp(prefix="ssc_headless_")
        self.addCleanup(__import__("shutil").rmtree, out, True)
        script = textwrap.dedent(f"""
            import ssc_twin, gymnasium as gym
            from gymnasium.utils.env_checker import check_env
            check_env(gym.make("ssc_twin/EdgeFollowing-v0", scene="disk_benchmark_fast").unwrapped)
            print("check_env passed")
            env = gym.make("ssc_twin/EdgeFollowing-v0", scene="disk_benchmark_fast",
                           render_mode="rgb_array", width=64, height=48)
            env.reset(seed=1)
            print("frame", env.render().shape)
            print("modes", env.unwrapped.metadata["render_modes"])
            def boom(reading):
                raise ValueError("boom")
            env = gym.make("ssc_twin/EdgeFollowing-v0", scene="disk_benchmark_fast",
                           controller=boom)
            env.reset(seed=1)
            info = env.step([0, 0])[-1]
            print("detail", info["detail"])
            r = ssc_twin.objects(["disk_d14"], out_dir={os.path.join(out, "o")!r}, seeds=1)
            print("objects", r["trials"] if isinstance(r, dict) and "trials" in r else "ran")
            """)
        env = {
            k: v
            for k, v in os.environ.items()
            if k not in ("DISPLAY", "WAYLAND_DISPLAY", "MUJOCO_GL", "PYOPENGL_PLATFORM")
        }
        r = subprocess.run(
            [sys.executable, "-c", script],
            capture_output=True,
            text=True,
            env=env,
            timeout=600,
            cwd=out,
        )
        self.assertEqual(r.returncode, 0, r.stderr[-3000:])
        self.assertIn("check_env passed", r.stdout)
        self.assertIn("frame (48, 64, 3)", r.stdout)
        self.assertIn("modes ['rgb_array']", r.stdout)
        self.assertIn("ValueError: boom", r.stdout)
        self.assertIn("objects", r.stdout)
        self.assertNotIn("leaked", r.stderr)


if __name__ == "__main__":
    unittest.main()
