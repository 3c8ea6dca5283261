"""Stage 1, the front end: OS2 text to the scenario model (``parse_file``, ``parse_text``)."""

from .errors import Diagnostic, OscError, SourceLocation
from .model import Actor, Argument, Composition, Invocation, Modifier, Name, OscFile, Quantity, Range, Scenario
from .parser import parse_file, parse_text

__all__ = [
    "Actor", "Argument", "Composition", "Diagnostic", "Invocation", "Modifier", "Name", "OscError",
    "OscFile", "Quantity", "Range", "Scenario", "SourceLocation", "parse_file", "parse_text",
]
