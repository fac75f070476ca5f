"""HarvestEnv: the IMA harvest as a Gymnasium environment (docs/python.md).

Action (8 values in [-1, 1]): forceps dx, dy, dz, jaw (> 0 closes, < 0 opens), hook dx, dy, dz,
pedal (> 0.5 cut, < -0.5 coagulate). The translations move each instrument's tool pose by up to
MAX_TOOL_SPEED (m/s) over the action's PHYSICS_STEPS_PER_ACTION steps of 5 ms.
Observation (18 float32): OBSERVATION_NAMES.
Reward: REWARD["progress"] times the share of the pedicle's strands divided this action, minus
REWARD["injury"] per IMA injury, minus REWARD["force_per_n"] per newton of either instrument's
normal force (eq. 17) above the trainee metrics' excessive force (4 N), minus REWARD["time"] per action.
Terminated: the pedicle divided, or the IMA injured. Truncated: the episode's time is up, or
the physics refused a step.
"""

import numpy as np

from . import _core
from .spaces import Box as _FallbackBox

try:  # Gymnasium when installed (Debian does not ship it); the same API without it
    import gymnasium as _gym
    _Env = _gym.Env
    _Box = _gym.spaces.Box
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _Env = object
    _Box = _FallbackBox


class HarvestEnv(_Env):
    metadata = {"render_modes": ["rgb_array"], "render_fps": 50}

    def __init__(self, scene=None, static=False, episode_seconds=60.0, power_w=40.0,
                 render_mode=None, render_size=(320, 240)):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode {render_mode!r}: None or 'rgb_array'")
        self.render_mode = render_mode
        self.render_size = tuple(render_size)
        self.core = _core.HarvestCore(scene=scene, static=static,
                                      episode_seconds=episode_seconds, power_w=power_w)
        self.action_space = _Box(-1.0, 1.0, shape=(_core.ACTION_SIZE,), dtype=np.float32)
        self.observation_space = _Box(-np.inf, np.inf, shape=(_core.OBSERVATION_SIZE,),
                                      dtype=np.float32)
        self._started = False

    def reset(self, *, seed=None, options=None):
        if _gym is not None:
            super().reset(seed=seed)
        if seed is not None:
            self.action_space.seed(seed)
        obs, _, _, _, info = self.core.reset(seed=seed)
        self._started = True
        return obs, info

    def step(self, action):
        if not self._started:
            raise RuntimeError("HarvestEnv.step before reset")
        return self.core.step(np.asarray(action, dtype=np.float32))

    @property
    def session(self):
        """The Session underneath: state(), events(), state_hash(), render()."""
        return self.core.session

    def render(self):
        if self.render_mode != "rgb_array":
            return None
        width, height = self.render_size
        return self.core.session.render(width, height)

    def close(self):
        pass


def rollout(envs, actions):
    """Steps each environment through its actions, each on a thread of its own.

    envs: HarvestEnv objects, each reset; actions: an array of len(envs) x T x 8.
    Returns (observations, rewards, terminated, truncated), arrays of len(envs) x T (x 18).
    An episode that ends repeats its last observation and earns nothing after.
    """
    return _core.rollout([e.core for e in envs], np.asarray(actions, dtype=np.float32))
