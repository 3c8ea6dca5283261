"""The layout's promises: the pytest plugin stays cheap to load, and every module imports on its own."""

import pkgutil
import subprocess
import sys

import pytest_roadlogic

HEAVY = ("clingo", "clingodl", "frenetix", "commonroad", "matplotlib", "antlr4", "hypothesis")


def test_loading_the_plugin_imports_nothing_heavy():
    # every pytest session in an environment with the package installed loads the plugin
    code = f"import sys, pytest_roadlogic.plugin; print(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r})))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]", f"the plugin module loaded {done.stdout.strip()}"


def test_every_module_imports_first_without_a_cycle():
    modules = [m.name for m in pkgutil.walk_packages(pytest_roadlogic.__path__, "pytest_roadlogic.") if ".generated" not in m.name]
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
