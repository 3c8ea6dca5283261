"""The layout's promises: the pytest plugin stays cheap to load, and every module imports on its own."""

import ast
import pkgutil
import re
import subprocess
import sys
from pathlib import Path

import pytest_roadlogic

HEAVY = ("clingo", "clingodl", "frenetix", "commonroad", "matplotlib", "antlr4", "hypothesis")


def test_loading_the_plugin_imports_nothing_heavy():
    # every pytest session in an environment with the package installed loads the plugin
    code = (
        f"import sys, pytest_roadlogic.plugin; print(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r})))"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]", f"the plugin module loaded {done.stdout.strip()}"


def test_every_module_imports_first_without_a_cycle():
    modules = [
        m.name
        for m in pkgutil.walk_packages(pytest_roadlogic.__path__, "pytest_roadlogic.")
        if ".generated" not in m.name and not m.name.endswith(".__main__")  # __main__ runs the command
    ]
    code = (
        "import importlib, sys\n"
        f"for name in {modules!r}:\n"
        "    for loaded in [m for m in sys.modules if m.startswith('pytest_roadlogic')]:\n"
        "        del sys.modules[loaded]\n"
        "    try:\n"
        "        importlib.import_module(name)\n"
        "    except ImportError as error:\n"
        "        print(name, error)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "", f"modules that fail to import when imported first:\n{done.stdout}"


def test_a_session_without_osc_files_loads_nothing_heavy_for_the_plugin(tmp_path):
    # configuring the plugin (its settings, the simulator names) must not load a stage either
    code = (
        "import sys, pytest\n"
        f"pytest.main(['--collect-only', '-q', '-p', 'no:cacheprovider', '--rootdir', {str(tmp_path)!r}, {str(tmp_path)!r}])\n"
        f"print(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r}) - {{'hypothesis'}}))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip().splitlines()[-1] == "[]", done.stdout + done.stderr


def test_ruff_finds_nothing_to_lint_or_to_format():
    """The style is ruff's, configured in pyproject.toml: a change that breaks it fails here."""
    root = Path(pytest_roadlogic.__file__).resolve().parents[1]
    for command in (["check", "."], ["format", "--check", "."]):
        done = subprocess.run([sys.executable, "-m", "ruff", *command], cwd=root, capture_output=True, text=True)
        assert done.returncode == 0, f"ruff {' '.join(command)}:\n{done.stdout}{done.stderr}"


def import_graph() -> tuple[dict[str, set[str]], list[tuple[str, str, str]]]:
    """The package's modules and what each imports, read from the source: imports inside functions
    and under TYPE_CHECKING too, and the packages an import runs (importing a.b.c runs a and
    a.b first). Also every import of another module's private name (module, source, name)."""
    package = Path(pytest_roadlogic.__file__).resolve().parent
    files = {
        p: p.relative_to(package.parent).with_suffix("").parts
        for p in package.rglob("*.py")
        if "generated" not in p.parts
    }
    modules = {".".join(parts[:-1] if parts[-1] == "__init__" else parts): path for path, parts in files.items()}

    def known(name: str) -> str:
        while name not in modules and "." in name:
            name = name.rsplit(".", 1)[0]
        return name

    def with_packages(name: str) -> set[str]:
        parts = name.split(".")
        return {".".join(parts[:k]) for k in range(1, len(parts) + 1)} & set(modules)

    edges: dict[str, set[str]] = {}
    private: list[tuple[str, str, str]] = []
    for module, path in modules.items():
        here = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
        targets: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets |= {known(a.name) for a in node.names if a.name.startswith("pytest_roadlogic")}
            elif isinstance(node, ast.ImportFrom):
                base = (
                    ".".join([*here[: len(here) - node.level + 1], *([node.module] if node.module else [])])
                    if node.level
                    else node.module
                )
                if not base or not base.startswith("pytest_roadlogic"):
                    continue
                for alias in node.names:
                    if f"{base}.{alias.name}" in modules:
                        targets.add(f"{base}.{alias.name}")
                    else:
                        targets.add(known(base))
                        if alias.name.startswith("_") and not alias.name.startswith("__"):
                            private.append((module, known(base), alias.name))
        edges[module] = set().union(*(with_packages(t) for t in targets)) - with_packages(module)
    return edges, private


def knots(edges: dict[str, set[str]]) -> list[set[str]]:
    """The strongly connected groups of more than one module (Tarjan's algorithm, iteratively)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[set[str]] = []
    for start in edges:
        if start in index:
            continue
        work = [(start, iter(sorted(edges[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    work.append((child, iter(sorted(edges.get(child, ())))))
                elif child in stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = set()
                while True:
                    member = stack.pop()
                    group.add(member)
                    if member == node:
                        break
                if len(group) > 1:
                    found.append(group)
    return found


def test_no_module_imports_another_modules_private_name():
    _, private = import_graph()
    assert private == [], private


def test_no_import_circle():
    """A circle of imports (inside functions too) makes the order of loading matter and a stage
    impossible to use alone. The last one (the checker, the constructs and the automaton) was cut
    by the guard algebra's own package (``logic``) and the registries looked up by dialect."""
    assert knots(import_graph()[0]) == []


# third-party integration points that are named with an underscore by their owners: os._exit (the
# documented way out of a process whose threads hang) and the attribute Hypothesis's own pytest
# integration sets for a database key per item
FOREIGN_PRIVATE = {"_exit", "_hypothesis_internal_add_digest"}
# modules that speak only the planner's, the simulation's and the reaction's protocols
PROTOCOL_ONLY = ("pipeline.py", "planning/__init__.py", "planning/fallbacks.py", "simulation/lockstep.py")


def package_sources() -> dict[Path, ast.Module]:
    package = Path(pytest_roadlogic.__file__).resolve().parent
    return {
        path.relative_to(package): ast.parse(path.read_text(encoding="utf-8"))
        for path in sorted(package.rglob("*.py"))
        if "generated" not in path.parts
    }


def test_no_module_uses_a_private_attribute_of_an_object_defined_elsewhere():
    """A private method or field is its module's: another module reaches it only through a protocol."""
    found = []
    for path, tree in package_sources().items():
        own = {
            node.name
            for node in ast.walk(tree)
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
        } | {
            target.attr
            for node in ast.walk(tree)
            if isinstance(node, ast.Assign)
            for target in node.targets
            if isinstance(target, ast.Attribute)
        }
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__")):
                continue
            owner = node.value
            if isinstance(owner, ast.Name) and owner.id in ("self", "cls"):
                continue
            if isinstance(owner, ast.Call) and isinstance(owner.func, ast.Name) and owner.func.id == "super":
                continue
            if node.attr in own or node.attr in FOREIGN_PRIVATE:
                continue
            found.append(f"{path}:{node.lineno}: {ast.unparse(node)}")
    assert found == []


def test_no_module_outside_an_encodings_folder_imports_its_internals():
    """An encoding is its folder: the rest of the tool reaches it through ``planning.encodings``'
    registry and the protocol, never through its modules (``encodings/<name>/planner.py`` ...)."""
    found = []
    for path, tree in package_sources().items():
        if path.parts[:2] == ("planning", "encodings"):
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and ".encodings." in f".{node.module}":
                name = node.module.split("encodings.", 1)[1]
                if "." in name:
                    found.append(f"{path}:{node.lineno}: from {node.module}")
    assert found == []


def test_the_pipeline_fallbacks_and_lockstep_probe_no_object_for_a_capability():
    """Capabilities are declared in the protocols (``planning.protocol``, ``simulation.driver``,
    ``simulation.interface``) and every implementation answers them: no ``hasattr``/``getattr``."""
    found = [
        f"{path}:{node.lineno}: {ast.unparse(node)}"
        for path, tree in package_sources().items()
        if path.as_posix() in PROTOCOL_ONLY
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in ("hasattr", "getattr")
    ]
    assert found == []


SOURCE_PATH = re.compile(r"(?<![\w/.])((?:[A-Za-z_][\w.-]*/)+[\w-]+\.(?:py|lp))\b")


def test_every_source_file_the_package_docs_and_encodings_name_exists():
    """A path in a docstring, a comment, an encoding's header or the architecture docs is a
    promise to a reader: it names a file that exists (relative to the repository, asp/, the package,
    or the package's planning, simulation or frontend folder)."""
    root = Path(pytest_roadlogic.__file__).resolve().parents[1]
    package = root / "pytest_roadlogic"
    bases = (root, root / "asp", package, package / "planning", package / "simulation", package / "frontend")
    texts = [
        *(p for p in package.rglob("*.py") if "generated" not in p.parts),
        *root.glob("asp/**/*.lp"),
        root / "docs" / "architecture.md",
        root / "CONTRIBUTING.md",
    ]
    stale = [
        f"{text.relative_to(root)}:{number}: {match.group(1)}"
        for text in texts
        for number, line in enumerate(text.read_text(encoding="utf-8").splitlines(), 1)
        for match in SOURCE_PATH.finditer(line)
        if not any((base / match.group(1)).exists() for base in bases)
    ]
    assert stale == []


# the marks of a measurement or of an issue's story in a comment or docstring: they belong in
# docs/decisions.md and the CHANGELOG, the code keeps what and why
HISTORY = re.compile(
    r"\bissue \d+\b|\bMeasured\b|\bmeasured (on|over|with)\b|\bhad (been|run|grown|taken|cost|printed)\b"
)


def test_the_code_keeps_what_and_why_and_leaves_measurements_and_issue_stories_to_the_docs():
    root = Path(pytest_roadlogic.__file__).resolve().parents[1]
    texts = [
        *(p for p in (root / "pytest_roadlogic").rglob("*.py") if "generated" not in p.parts),
        *root.glob("asp/**/*.lp"),
    ]
    notes = [
        f"{text.relative_to(root)}:{number}: {line.strip()[:100]}"
        for text in texts
        for number, line in enumerate(text.read_text(encoding="utf-8").splitlines(), 1)
        if HISTORY.search(line)
    ]
    assert notes == []


def test_the_front_ends_syntax_never_imports_its_semantics():
    syntax = Path(pytest_roadlogic.__file__).resolve().parent / "frontend" / "syntax"
    found = [
        f"{path.name}:{number}: {line.strip()}"
        for path in syntax.glob("*.py")
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if re.match(r"\s*(from|import) \S*semantics\b", line)
    ]
    assert found == []


def test_the_commands_help_loads_no_command_and_a_command_loads_only_itself():
    # `roadlogic --help` is answered before any command's flags (the option table) exist
    code = (
        "import sys, contextlib, io\n"
        "from pytest_roadlogic.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(SystemExit):\n"
        "    main(sys.argv[1:])\n"
        "print(sorted(m for m in sys.modules if m.startswith('pytest_roadlogic.cli.') or m == 'pytest_roadlogic.settings'))\n"
    )
    loaded = {}
    for argv in (["--help"], ["check", "--help"]):
        done = subprocess.run([sys.executable, "-c", code, *argv], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        loaded[argv[0]] = done.stdout.strip().splitlines()[-1]
    assert loaded["--help"] == "['pytest_roadlogic.cli.commands']"
    assert "pytest_roadlogic.cli.check" in loaded["check"] and "pytest_roadlogic.cli.run'" not in loaded["check"]
