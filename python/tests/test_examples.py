"""The examples run as a user would run them."""

import subprocess
import sys


def test_the_random_policy_example_runs(source_dir):
    out = subprocess.run([sys.executable, str(source_dir / "python/examples/random_policy.py"),
                          "--episodes", "1", "--seconds", "0.2"],
                         capture_output=True, text=True, check=True)
    assert "episode 0" in out.stdout


def test_the_rescoring_example_scores_a_recording(source_dir, imasim_binary, tmp_path):
    csv = tmp_path / "session.csv"
    subprocess.run([imasim_binary, "run", "--headless", "--seconds", "1.5", "--script",
                    str(source_dir / "examples/open_fascia.script"), "--record", str(csv),
                    "--no-db", "--json"], capture_output=True, text=True, check=True)
    out = subprocess.run([sys.executable, str(source_dir / "python/examples/rescore.py"),
                          str(csv)], capture_output=True, text=True, check=True)
    assert "hook" in out.stdout and "path length" in out.stdout
