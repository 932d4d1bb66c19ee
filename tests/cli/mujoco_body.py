"""A body's inertial as MuJoCo compiled it, in the body frame like the
audit's: mass, centre of mass, and the tensor about it (MuJoCo keeps the
principal moments and the quaternion of their axes). Needs mujoco and numpy
(the Python test venv); the tests and tests/benchmark/audit_vs_mujoco.py use
it."""

import mujoco
import numpy as np


def body_inertial(model, body):
    """body: a name or an index."""
    b = model.body(body)
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, b.iquat)
    rotation = rotation.reshape(3, 3)
    return b.mass[0], np.array(b.ipos), rotation @ np.diag(b.inertia) @ rotation.T
