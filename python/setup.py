"""pip install --no-build-isolation ./python (from the repository root).

Builds the extension `unfold._core` with the repository's CMake project (the
same library as the command-line tools) and installs it with the package's
Python files into the active environment. Nothing is downloaded: the
dependencies are the Debian packages of scripts/setup.

UNFOLD_BUILD_DIR=path reuses a CMake build directory (e.g. build/, already
configured and built by scripts/setup: only the module's target is brought up
to date); otherwise the build goes to build/pip/ in the repository.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent.parent


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(unfold VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Builds the CMake target unfold_python and copies its _core module."""

    def build_extension(self, ext):
        build_dir = Path(os.environ.get("UNFOLD_BUILD_DIR") or ROOT / "build" / "pip").resolve()
        if not (build_dir / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release", "-DUNFOLD_BUILD_TESTS=OFF",
                            "-DUNFOLD_BUILD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"],
                           check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "unfold_python",
                        "-j", jobs], check=True)
        built = sorted((build_dir / "python" / "unfold").glob("_core*.so"))
        if not built:
            sys.exit(f"setup.py: CMake built no unfold/_core module in {build_dir} "
                     "(needs pybind11-dev, python3-dev and python3-numpy)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


setup(
    name="unfold",
    version=version(),
    description="Detail-preserving unfolding of non-rigid 3D shapes into a canonical pose",
    # AGPL-3.0-or-later: TetGen (AGPL-3.0-or-later) and CGAL's skeletonization
    # (GPL-3.0-or-later) are linked in; LICENSE and the README's "Licence".
    license="AGPL-3.0-or-later",
    classifiers=["License :: OSI Approved :: GNU Affero General Public License v3 or later (AGPLv3+)"],
    python_requires=">=3.8",
    install_requires=["numpy"],
    packages=["unfold"],
    package_dir={"unfold": "unfold"},
    package_data={"unfold": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("unfold._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
