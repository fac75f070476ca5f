"""imasim.HarvestEnv (the Gymnasium API, with or without gymnasium) and imasim.rollout."""

import numpy as np
import pytest

import imasim


def test_the_gymnasium_api_and_its_spaces():
    env = imasim.HarvestEnv(static=True, episode_seconds=1.0)
    assert env.action_space.shape == (imasim.ACTION_SIZE,) == (8,)
    assert env.observation_space.shape == (imasim.OBSERVATION_SIZE,) == (18,)
    assert len(imasim.OBSERVATION_NAMES) == imasim.OBSERVATION_SIZE
    obs, info = env.reset(seed=1)
    assert isinstance(info, dict)
    assert obs.dtype == np.float32 and obs.shape == (18,)
    assert env.observation_space.contains(obs)
    action = env.action_space.sample()
    assert env.action_space.contains(action)
    obs, reward, terminated, truncated, info = env.step(action)
    assert obs.shape == (18,) and np.all(np.isfinite(obs))
    assert np.isfinite(reward)
    assert terminated in (False, True) and truncated in (False, True)
    assert set(info) >= {"pedicle_divided", "ima_injuries", "max_force_n"}


def test_an_idle_episode_is_truncated_at_its_time_and_pays_only_time():
    env = imasim.HarvestEnv(static=True, episode_seconds=0.2)
    env.reset(seed=2)
    steps, total = 0, 0.0
    while True:
        _, reward, terminated, truncated, _ = env.step(np.zeros(8, dtype=np.float32))
        steps += 1
        total += reward
        if terminated or truncated:
            break
    # 0.2 s of 4 steps of 5 ms: 10 actions, each charged the time penalty only.
    assert steps == 10 and truncated and not terminated
    assert total == pytest.approx(-10 * imasim.REWARD["time"])


def test_moving_a_tool_moves_its_tip_by_the_actions_bound():
    env = imasim.HarvestEnv(static=True)
    obs0, _ = env.reset(seed=1)
    action = np.zeros(8, dtype=np.float32)
    action[6] = -1.0  # the hook towards -z (away from the tissue ahead of it)
    for _ in range(5):
        obs, *_ = env.step(action)
    travel = 5 * imasim.MAX_TOOL_SPEED * imasim.PHYSICS_STEPS_PER_ACTION * env.session.dt
    assert obs[5] - obs0[5] == pytest.approx(-travel, rel=0.05)
    assert abs(obs[3] - obs0[3]) < 0.2 * travel


def test_the_same_seed_and_actions_give_the_same_bits():
    rng = np.random.default_rng(7)
    actions = rng.uniform(-1, 1, size=(15, 8)).astype(np.float32)
    hashes, observations = [], []
    for _ in range(2):
        env = imasim.HarvestEnv(static=False)
        env.reset(seed=11)
        for a in actions:
            obs, *_ = env.step(a)
        hashes.append(env.session.state_hash())
        observations.append(obs)
    assert hashes[0] == hashes[1]
    assert np.array_equal(observations[0], observations[1])


def test_rollout_on_threads_gives_what_stepping_one_by_one_gives():
    rng = np.random.default_rng(3)
    actions = rng.uniform(-1, 1, size=(2, 12, 8)).astype(np.float32)
    envs = [imasim.HarvestEnv(), imasim.HarvestEnv()]
    for k, e in enumerate(envs):
        e.reset(seed=20 + k)
    obs, rewards, terminated, truncated = imasim.rollout(envs, actions)
    assert obs.shape == (2, 12, 18) and rewards.shape == (2, 12)
    assert terminated.shape == truncated.shape == (2, 12)
    for k in range(2):
        alone = imasim.HarvestEnv()
        alone.reset(seed=20 + k)
        for t in range(12):
            o, r, *_ = alone.step(actions[k, t])
            assert np.array_equal(o, obs[k, t])
            assert r == rewards[k, t]
        assert alone.session.state_hash() == envs[k].session.state_hash()


def test_render_mode_rgb_array():
    env = imasim.HarvestEnv(static=True, render_mode="rgb_array", render_size=(96, 64))
    env.reset(seed=1)
    frame = env.render()
    assert frame.shape == (64, 96, 3) and frame.dtype == np.uint8
    assert imasim.HarvestEnv().render() is None


def test_bad_actions_and_arguments_are_refused():
    env = imasim.HarvestEnv()
    with pytest.raises(RuntimeError, match="before reset"):
        env.step(np.zeros(8))
    env.reset(seed=1)
    with pytest.raises(ValueError, match="8 values"):
        env.step(np.zeros(7))
    with pytest.raises(ValueError, match="not finite"):
        env.step(np.array([0, 0, np.inf, 0, 0, 0, 0, 0]))
    with pytest.raises(ValueError, match="render_mode"):
        imasim.HarvestEnv(render_mode="human")
    with pytest.raises(ValueError, match="episode_seconds"):
        imasim.HarvestEnv(episode_seconds=0)
    with pytest.raises(ValueError, match="n_envs x T x 8"):
        imasim.rollout([env], np.zeros((2, 3, 8)))
    with pytest.raises(ValueError, match="given twice"):
        imasim.rollout([env, env], np.zeros((2, 3, 8)))
    with pytest.raises(ValueError, match="before reset"):
        imasim.rollout([imasim.HarvestEnv()], np.zeros((1, 2, 8)))


def test_the_fallback_box_behaves_as_gymnasiums():
    box = imasim.Box(-1.0, 1.0, shape=(4,), seed=5)
    samples = np.array([box.sample() for _ in range(200)])
    assert samples.dtype == np.float32 and samples.shape == (200, 4)
    assert samples.min() >= -1 and samples.max() <= 1 and samples.std() > 0.4
    assert box.contains(np.zeros(4, dtype=np.float32))
    assert not box.contains(np.full(4, 2, dtype=np.float32))
    assert not box.contains(np.zeros(3, dtype=np.float32))
    again = imasim.Box(-1.0, 1.0, shape=(4,), seed=5)
    assert np.array_equal(again.sample(), samples[0])
