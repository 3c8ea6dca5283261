"""The files of this folder are written for CARLA's scenario runner (lanes numbered from the left,
``speed(v)`` a target speed): pytest reads them in that dialect."""


def pytest_roadlogic_dialect(config, path):
    return "carla"
