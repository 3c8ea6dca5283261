"""The front end's syntax: ``.osc`` text (the ANTLR grammar in ``grammar/``, its generated parser,
the layout-aware lexer) read into the scenario model (``frontend.model``) with the standard
library's units, within the input limits. Nothing here resolves a name or a type."""
