"""Builds the Python package's native module with the project's CMake (pyproject.toml holds the
metadata). `python3 -m pip install --no-build-isolation .` runs it; docs/PYTHON.md.

The module, foresight/_foresight*.so, is the CMake target foresight_python; the shipped data
(models/) goes into the package as foresight/models, where the module looks first. By default
CMake configures and builds in build/pip/cmake (Release, without tests and benchmarks; a first
build takes minutes). FORESIGHT_CMAKE_BUILD_DIR=DIR uses an existing build folder instead (it is
built, not reconfigured), so a developer's build is reused.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
# The data files of models/ (the C++ sources of the models library live beside them).
DATA_SKIP = shutil.ignore_patterns("*.h", "*.cc", "CMakeLists.txt")


def project_version():
    """The version of CMakeLists.txt's project() call: one place for it."""
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(foresight VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Builds the foresight_python target with CMake and copies the module and models/."""

    def build_extension(self, ext):
        given = os.environ.get("FORESIGHT_CMAKE_BUILD_DIR")
        build_dir = pathlib.Path(given).resolve() if given else ROOT / "build" / "pip" / "cmake"
        if not (build_dir / "CMakeCache.txt").exists():
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                 "-DFORESIGHT_BUILD_TESTS=OFF", "-DFORESIGHT_BUILD_BENCH=OFF",
                 f"-DPython3_EXECUTABLE={sys.executable}"],
                check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "foresight_python",
                        "-j", jobs], check=True)
        built = sorted((build_dir / "python" / "foresight").glob("_foresight*.so"))
        if not built:
            raise RuntimeError(f"no foresight/_foresight*.so in {build_dir}/python")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        models = target.parent / "models"
        if models.exists():
            shutil.rmtree(models)
        shutil.copytree(ROOT / "models", models, ignore=DATA_SKIP)


(ROOT / "build" / "pip").mkdir(parents=True, exist_ok=True)  # egg_info's folder must exist
setup(
    version=project_version(),
    ext_modules=[Extension("foresight._foresight", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build and metadata folders inside CMake's build/, not beside the sources.
    options={"build": {"build_base": str(ROOT / "build" / "pip")},
             "egg_info": {"egg_base": str(ROOT / "build" / "pip")}},
    zip_safe=False,
)
