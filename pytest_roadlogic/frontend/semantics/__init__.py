"""The front end's semantics: a parsed file's imports loaded, its names, types, events,
invocations and inheritance resolved, its values evaluated, its parameters given their domains and
their one identity (``logical``), and its road's lanes counted: a ``CheckedFile`` of
``CheckedScenario``s, what every later stage takes (``checker.check_file``)."""
