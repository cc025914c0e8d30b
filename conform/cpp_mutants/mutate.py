"""Build the C++ mutants of mutants.toml into throwaway binding modules (and, with
--gtest, GoogleTest executables), all in ONE CMake tree:

    python conform/cpp_mutants/mutate.py BUILD_DIR [--gtest] [--only ID ...]

Each mutation is applied to a copy of its file under BUILD_DIR/patched/<id>/ (the
build fails when `original` does not occur exactly once: the mutation no longer
applies).  Every unmutated translation unit is compiled once (an OBJECT library);
per mutant only the TUs that are, or include, the mutated file are compiled again,
with the patched include folder first.  Module: `safestate_mut_<id>._core` with
BUILD_DIR on sys.path; GoogleTest: BUILD_DIR/gtest_<id>/test_*.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


class MutationError(Exception):
    pass


@dataclass(frozen=True)
class Mutant:
    id: str
    kind: str
    what: str
    file: str
    original: str
    replacement: str


def load(path: Path = HERE / "mutants.toml") -> list[Mutant]:
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    return [Mutant(**m) for m in doc["mutant"]]


def apply(m: Mutant, root: Path = REPO) -> str:
    text = (root / m.file).read_text(encoding="utf-8")
    n = text.count(m.original)
    if n != 1:
        raise MutationError(f"mutant {m.id}: the original text occurs {n} times in {m.file} (expected once): "
                            f"the mutation no longer applies")
    return text.replace(m.original, m.replacement)


def _includes(path: Path, seen: set[Path]) -> set[Path]:
    """Files `path` includes, transitively (project headers only)."""
    for inc in INCLUDE_RE.findall(path.read_text(encoding="utf-8")):
        for base in (path.parent, REPO / "include"):
            p = (base / inc).resolve()
            if p.is_file() and p not in seen:
                seen.add(p)
                _includes(p, seen)
                break
    return seen


def translation_units(gtest: bool) -> dict[str, Path]:
    tus = {f"src_{p.stem}": p for p in sorted((REPO / "src").glob("*.cpp"))}
    tus["binding"] = REPO / "bindings" / "python" / "core_module.cpp"
    if gtest:
        tus.update({f"test_{p.stem}": p for p in sorted((REPO / "tests" / "cpp").glob("test_*.cpp"))})
    return tus


def affected(m: Mutant, tus: dict[str, Path]) -> set[str]:
    target = (REPO / m.file).resolve()
    return {name for name, p in tus.items() if p.resolve() == target or target in _includes(p, set())}


def cmake_text(mutants: list[Mutant], gtest: bool, build: Path) -> str:
    tus = translation_units(gtest)
    lines = [
        "cmake_minimum_required(VERSION 3.25)",
        "project(safestate_cpp_mutants LANGUAGES CXX)",
        "set(CMAKE_CXX_STANDARD 17)", "set(CMAKE_CXX_STANDARD_REQUIRED ON)",
        "set(CMAKE_POSITION_INDEPENDENT_CODE ON)",
        # Several mutant modules are loaded into one process: with default visibility an
        # inline variable (the constexpr transition table kRows) is a GNU-unique symbol,
        # bound process-wide to the FIRST module loaded, so a later mutant would run the
        # first one's table (and guards).  Hidden symbols bind within their own module.
        "set(CMAKE_CXX_VISIBILITY_PRESET hidden)", "set(CMAKE_VISIBILITY_INLINES_HIDDEN ON)",
        "add_compile_options(-fno-gnu-unique)",
        "find_package(Eigen3 3.3 REQUIRED NO_MODULE)",
        "find_package(Python COMPONENTS Interpreter Development.Module REQUIRED)",
        "find_package(pybind11 CONFIG REQUIRED)",
    ]
    if gtest:
        lines.append("find_package(GTest REQUIRED)")
    repo = REPO.as_posix()

    def obj(name: str, src: str, incs: list[str]) -> None:
        lines.append(f"add_library({name} OBJECT {src})")
        lines.append(f"target_include_directories({name} PRIVATE {' '.join(incs)} {repo}/include {repo}/tests/cpp)")
        libs = "Eigen3::Eigen pybind11::module" if "binding" in name else "Eigen3::Eigen"
        if "test_" in name:
            libs += " GTest::gtest"
            lines.append(f'target_compile_definitions({name} PRIVATE SAFESTATE_SOURCE_DIR="{repo}")')
        lines.append(f"target_link_libraries({name} PRIVATE {libs})")

    for name, p in tus.items():
        obj(f"orig_{name}", p.as_posix(), [])
    for m in mutants:
        hit = affected(m, tus)
        patched_root = (build / "patched" / m.id).as_posix()
        objs: dict[str, str] = {}
        for name, p in tus.items():
            if name in hit:
                rel = p.resolve().relative_to(REPO)
                src = f"{patched_root}/{rel.as_posix()}" if rel.as_posix() == m.file else p.as_posix()
                obj(f"m_{m.id}_{name}", src, [f"{patched_root}/include"])
                objs[name] = f"$<TARGET_OBJECTS:m_{m.id}_{name}>"
            else:
                objs[name] = f"$<TARGET_OBJECTS:orig_{name}>"
        lib = " ".join(v for k, v in objs.items() if k.startswith("src_"))
        lines.append(f"pybind11_add_module(mut_{m.id} MODULE NO_EXTRAS {objs['binding']} {lib})")
        lines.append(f"target_link_libraries(mut_{m.id} PRIVATE Eigen3::Eigen)")
        lines.append(f"set_target_properties(mut_{m.id} PROPERTIES OUTPUT_NAME _core "
                     f"LIBRARY_OUTPUT_DIRECTORY ${{CMAKE_BINARY_DIR}}/safestate_mut_{m.id})")
        if gtest:
            for name in [k for k in tus if k.startswith("test_")]:
                exe = f"gt_{m.id}_{name[5:]}"
                lines.append(f"add_executable({exe} {objs[name]} {lib})")
                lines.append(f"target_link_libraries({exe} PRIVATE Eigen3::Eigen GTest::gtest GTest::gtest_main)")
                lines.append(f"set_target_properties({exe} PROPERTIES OUTPUT_NAME {name[5:]} "
                             f"RUNTIME_OUTPUT_DIRECTORY ${{CMAKE_BINARY_DIR}}/gtest_{m.id})")
    return "\n".join(lines) + "\n"


def prepare(build: Path, mutants: list[Mutant], gtest: bool) -> None:
    """Write the patched files and the CMakeLists.txt (fails if a mutation no longer applies)."""
    build.mkdir(parents=True, exist_ok=True)
    for m in mutants:
        out = build / "patched" / m.id / m.file
        out.parent.mkdir(parents=True, exist_ok=True)
        text = apply(m)
        if not out.exists() or out.read_text(encoding="utf-8") != text:
            out.write_text(text, encoding="utf-8")
        pkg = build / f"safestate_mut_{m.id}"
        pkg.mkdir(exist_ok=True)
        (pkg / "__init__.py").touch()
    src = build / "src"
    src.mkdir(exist_ok=True)
    cm = src / "CMakeLists.txt"
    text = cmake_text(mutants, gtest, build)
    if not cm.exists() or cm.read_text(encoding="utf-8") != text:
        cm.write_text(text, encoding="utf-8")


def build_all(build: Path, mutants: list[Mutant], gtest: bool = False, jobs: int = 1) -> None:
    prepare(build, mutants, gtest)
    py = os.environ.get("PYTHON", sys.executable)
    pybind_dir = subprocess.run([py, "-m", "pybind11", "--cmakedir"], check=True, capture_output=True,
                                text=True).stdout.strip()
    if not (build / "build.ninja").exists():
        subprocess.run(["cmake", "-S", str(build / "src"), "-B", str(build), "-G", "Ninja",
                        # -O1: the modules run one input-complete pass each; -O3 cost more to
                        # compile than the pass saves.
                        "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG",
                        f"-DPython_EXECUTABLE={py}", f"-Dpybind11_DIR={pybind_dir}"],
                       check=True, stdout=subprocess.DEVNULL)
    targets = [f"mut_{m.id}" for m in mutants]
    if gtest:
        targets = ["all"]
    subprocess.run(["cmake", "--build", str(build), "-j", str(jobs), "--target", *targets], check=True,
                   stdout=subprocess.DEVNULL)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build", type=Path)
    ap.add_argument("--gtest", action="store_true", help="also build GoogleTest executables per mutant")
    ap.add_argument("--only", nargs="+", metavar="ID")
    ap.add_argument("-j", "--jobs", type=int, default=1)
    a = ap.parse_args()
    mutants = [m for m in load() if not a.only or m.id in a.only]
    try:
        build_all(a.build.resolve(), mutants, a.gtest, a.jobs)
    except MutationError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    print(a.build.resolve())
    return 0


if __name__ == "__main__":
    sys.exit(main())
