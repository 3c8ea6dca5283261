"""OpenDRIVE written by the project (``opendrive_xml``): the same bytes for the same road.

scenariogeneration stamps a file's header with the time of writing; here the header carries a fixed
date, so that one seed writes the same artifacts on every run and machine, and the committed test
maps are what their recipe writes.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

# the header's date of every OpenDRIVE file the project writes
OPENDRIVE_DATE = "2026-01-01T00:00:00"


def opendrive_xml(opendrive) -> bytes:
    """The file of a ``scenariogeneration.xodr.OpenDrive``, indented, with the fixed header date."""
    root = opendrive.get_element()
    header = root.find("header")
    if header is not None:
        header.set("date", OPENDRIVE_DATE)
    ET.indent(root, space="    ")
    return ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n"


def write_maps(opendrives: dict, directory: Path) -> list[Path]:
    """Each ``scenariogeneration.xodr.OpenDrive`` of ``opendrives`` (file name -> map) as its file in
    ``directory`` (``opendrive_xml``); their paths. What the project's map recipes write."""
    written = []
    for name, opendrive in opendrives.items():
        path = Path(directory) / name
        path.write_bytes(opendrive_xml(opendrive))
        written.append(path)
    return written
