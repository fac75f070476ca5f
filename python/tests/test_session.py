"""imasim.Session: stepping, state as numpy arrays, commands, events, hashes, pictures."""

import json
import subprocess

import numpy as np
import pytest

import imasim


def test_steps_advance_time_and_state_is_arrays():
    s = imasim.Session(static=True)
    st = s.state()
    assert st["time"] == 0.0
    for name in ("fascia", "ima", "chest_wall", "ima_fat", "fascia_fat"):
        x = st["positions"][name]
        assert x.dtype == np.float64 and x.ndim == 2 and x.shape[1] == 3 and len(x) > 0
        assert np.all(np.isfinite(x))
    assert s.step(10) is True
    st = s.state()
    assert st["time"] == pytest.approx(10 * s.dt)
    assert st["steps"] == 10
    assert set(st["tools"]) == {"forceps", "hook"}
    hook = st["tools"]["hook"]
    assert hook["tip"].shape == (3,) and hook["pose"].shape == (4, 4)
    assert np.allclose(hook["pose"][3], [0, 0, 0, 1])
    assert st["pedal"] == "off"
    assert st["heart_beating"] is False


def test_the_same_commands_give_the_same_bits_and_other_commands_do_not():
    def run(dy):
        s = imasim.Session(seed=3)
        pose = s.state()["tools"]["hook"]["device_pose"].copy()
        pose[1, 3] += dy
        s.set_device_pose("hook", pose)
        s.step(40)
        return s.state_hash()

    a, b, c = run(0.003), run(0.003), run(0.0)
    assert len(a) == 16 and int(a, 16) >= 0
    assert a == b
    assert a != c


def test_a_python_session_replays_on_the_command_line_to_the_same_state(tmp_path, imasim_binary):
    stream = tmp_path / "stream.txt"
    s = imasim.Session()
    s.record_input(str(stream))
    pose = s.state()["tools"]["hook"]["device_pose"].copy()
    for k in range(6):
        pose[1, 3] += 0.0005
        s.set_device_pose(1, pose)
        s.grasp(close=k % 2 == 0)
        s.step(10)
    s.stop_recording()
    out = subprocess.run([imasim_binary, "run", "--headless", "--replay", str(stream), "--json"],
                         capture_output=True, text=True, check=True)
    report = json.loads(out.stdout)
    assert report["steps"] == 60
    assert report["state_hash"] == s.state_hash()


def rotation(rv):
    """The rotation of a rotation vector (axis times angle, rad), as the input script's."""
    rv = np.asarray(rv, dtype=float)
    angle = np.linalg.norm(rv)
    if angle == 0:
        return np.eye(3)
    k = rv / angle
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def test_the_hook_cuts_the_fascia_as_the_example_script_does():
    # examples/open_fascia.script's first cut: below the fascia, up through it, drawn caudally.
    s = imasim.Session(static=True)
    r = rotation([0.6212, -2.4501, -1.4125])
    keys = [(0.0, [0.0100, -0.0240, 0.0550]), (0.4, [0.0125, -0.0181, 0.0550]),
            (1.4, [0.0125, -0.0195, 0.0640])]
    for k in range(int(round(1.4 / s.dt))):
        t = k * s.dt
        a, b = (keys[0], keys[1]) if t < 0.4 else (keys[1], keys[2])
        f = min(1.0, (t - a[0]) / (b[0] - a[0]))
        s.set_device_pose("hook", np.asarray(a[1]) + f * (np.asarray(b[1]) - np.asarray(a[1])), r)
        s.cut(t >= 0.5)
        assert s.step(1)
    st = s.state()
    assert st["fascia_edges_cut"] > 0
    assert any(e["kind"] == "fascia_cut" and e["instrument"] == "hook" for e in s.events())
    assert st["ima_injuries"] == 0


def test_render_gives_an_rgb_picture_of_the_endoscope():
    s = imasim.Session(static=True)
    rgb = s.render(160, 120)
    assert rgb.shape == (120, 160, 3) and rgb.dtype == np.uint8
    assert rgb.std() > 5  # a picture, not a blank


def test_bad_requests_are_refused_with_their_reason(tmp_path):
    with pytest.raises(ValueError, match="missing.toml"):
        imasim.Session(scene=str(tmp_path / "missing.toml"))
    s = imasim.Session()
    with pytest.raises(ValueError, match="hand"):
        s.set_device_pose("elbow", np.zeros(3))
    with pytest.raises(ValueError, match="rotation"):
        s.set_device_pose(0, np.zeros(3), np.ones((3, 3)))
    with pytest.raises(ValueError, match="finite"):
        s.set_device_pose(0, np.array([np.nan, 0, 0]))
    with pytest.raises(ValueError, match="pedal mode"):
        s.cut(True, mode="blend")
    with pytest.raises(ValueError, match="power"):
        s.cut(True, power_w=500)
    with pytest.raises(ValueError, match="n >= 0"):
        s.step(-1)
