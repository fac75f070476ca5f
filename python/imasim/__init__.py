"""imasim: a real-time simulator of robotic internal mammary artery harvesting.

Session steps one surgical session (the built-in thorax or a scene file) with the input you
command; HarvestEnv is the harvest as a Gymnasium environment; rollout steps many on threads.
See docs/python.md.
"""

from ._core import (ACTION_SIZE, MAX_TOOL_SPEED, OBSERVATION_NAMES, OBSERVATION_SIZE,
                    PHYSICS_STEPS_PER_ACTION, REWARD, ImasimError, Session)
from .harvest_env import HarvestEnv, rollout
from .spaces import Box

__all__ = ["Session", "HarvestEnv", "rollout", "Box", "ImasimError", "ACTION_SIZE",
           "OBSERVATION_SIZE", "OBSERVATION_NAMES", "PHYSICS_STEPS_PER_ACTION",
           "MAX_TOOL_SPEED", "REWARD"]
