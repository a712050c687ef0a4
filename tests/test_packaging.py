"""The wheel carries the scheme and engine files (a plain, non-editable install finds them)."""

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.slow
def test_wheel_contains_scheme_and_engine_files(tmp_path):
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(ROOT)], check=True)
    (wheel,) = tmp_path.glob("stackup-*.whl")
    names = set(zipfile.ZipFile(wheel).namelist())
    for k in range(1, 7):
        assert f"stackup/_scheme_files/iso13778-{k}.toml" in names
    assert "stackup/data/engines/iso-example.toml" in names
