"""Stage 1, the front end: OS2 text to a checked scenario model.

``parse_file``/``parse_text`` read syntax only; ``check_file``/``check_text`` also load imports and
resolve names, types and parameter ranges into a ``CheckedFile`` of ``CheckedScenario``s (what
every later stage takes); ``load_file`` raises on any error.
"""

from .errors import Diagnostic, OscError, SourceLocation
from .model import Actor, Argument, Composition, Invocation, Modifier, Name, OscFile, Quantity, Range, Scenario
from .semantics.checked import CheckedFile, CheckedScenario
from .semantics.checker import check_file, check_text, load_file
from .semantics.parameters import ParameterDomain, ParameterSpace
from .syntax.parser import parse_file, parse_text

__all__ = [
    "Actor",
    "Argument",
    "CheckedFile",
    "CheckedScenario",
    "Composition",
    "Diagnostic",
    "Invocation",
    "Modifier",
    "Name",
    "OscError",
    "OscFile",
    "ParameterDomain",
    "ParameterSpace",
    "Quantity",
    "Range",
    "Scenario",
    "SourceLocation",
    "check_file",
    "check_text",
    "load_file",
    "parse_file",
    "parse_text",
]
