#!/usr/bin/python3
"""A random policy in the harvest (docs/python.md): the Gymnasium loop, with or without gymnasium.

    /usr/bin/python3 python/examples/random_policy.py --episodes 2 --seconds 5
"""

import argparse

import numpy as np

import imasim


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=2)
    parser.add_argument("--seconds", type=float, default=5.0, help="simulated time an episode")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    env = imasim.HarvestEnv(episode_seconds=args.seconds)
    for episode in range(args.episodes):
        obs, info = env.reset(seed=args.seed + episode)
        env.action_space.seed(args.seed + episode)
        total, steps, done = 0.0, 0, False
        while not done:
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            total += reward
            steps += 1
            done = terminated or truncated
        print(f"episode {episode}: {steps} actions, return {total:.3f}, "
              f"pedicle divided {info['pedicle_divided']:.3f}, IMA injuries "
              f"{info['ima_injuries']}, largest force {info['max_force_n']:.2f} N, "
              f"state {env.session.state_hash()}")
    env.close()


if __name__ == "__main__":
    main()
