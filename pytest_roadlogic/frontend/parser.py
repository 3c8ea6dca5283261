"""Reading ``.osc`` text into the scenario model.

``parse_text`` / ``parse_file`` run the generated ANTLR parser (through ``IndentingLexer``) and turn
the parse tree into ``model`` dataclasses. Syntax errors are collected, not printed, and raised
together as one ``OscError``.
"""

from __future__ import annotations

from pathlib import Path

from antlr4 import CommonTokenStream, InputStream
from antlr4.error.ErrorListener import ErrorListener

from . import model
from .errors import Diagnostic, OscError, SourceLocation
from .generated.OpenScenario2Parser import OpenScenario2Parser as P
from .lexer import IndentingLexer
from .units import UNITS, split_physical_literal


class _CollectingListener(ErrorListener):
    def __init__(self, path: str) -> None:
        self.path = path
        self.diagnostics: list[Diagnostic] = []

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):  # noqa: N802 (ANTLR API)
        text = getattr(offendingSymbol, "text", None)
        shown = {"\n": "end of line", "<EOF>": "end of file", "": "end of block"}.get(text, text)
        message = f"syntax error at {shown!r}: {msg}" if shown else f"syntax error: {msg}"
        self.diagnostics.append(Diagnostic(SourceLocation(self.path, line, column + 1), message))


def parse_text(text: str, path: str = "<string>") -> model.OscFile:
    """Parse OS2 source text; raise ``OscError`` naming every syntax error found."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    lexer = IndentingLexer(InputStream(text), path)
    listener = _CollectingListener(path)
    lexer.removeErrorListeners()
    lexer.addErrorListener(listener)
    parser = P(CommonTokenStream(lexer))
    parser.removeErrorListeners()
    parser.addErrorListener(listener)
    tree = parser.oscFile()
    diagnostics = lexer.diagnostics + listener.diagnostics
    if diagnostics:
        diagnostics.sort(key=lambda d: (d.location.line, d.location.column))
        raise OscError(diagnostics, text)
    return _Builder(path, text).file(tree)


def parse_file(path: str | Path) -> model.OscFile:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise OscError([Diagnostic(SourceLocation(str(path), 1, 1), f"the file is not valid UTF-8 ({exc.reason})")]) from None
    except OSError as exc:
        raise OscError([Diagnostic(SourceLocation(str(path), 1, 1), f"cannot read the file: {exc.strerror}")]) from None
    return parse_text(text, str(path))


class _Builder:
    """Turns parse-tree contexts into model nodes."""

    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.text = text

    def loc(self, ctx) -> SourceLocation:
        token = ctx.start if hasattr(ctx, "start") else ctx.symbol
        return SourceLocation(self.path, token.line, token.column + 1)

    def file(self, ctx: P.OscFileContext) -> model.OscFile:
        scenarios = [self.scenario(d.scenarioDeclaration()) for d in ctx.declaration()]
        return model.OscFile(self.path, tuple(scenarios), self.text)

    def scenario(self, ctx: P.ScenarioDeclarationContext) -> model.Scenario:
        name_ctx = ctx.scenarioName()
        actors: list[model.Actor] = []
        behaviors: list[model.Behavior] = []
        for member in ctx.scenarioMember():
            if member.fieldDeclaration() is not None:
                field = member.fieldDeclaration()
                type_name = field.typeName().getText()
                for ident in field.identifier():
                    actors.append(model.Actor(ident.getText(), type_name, self.loc(ident)))
            else:
                behaviors.append(self.behavior(member.doDirective().behavior()))
        if len(behaviors) > 1:
            raise OscError(
                [Diagnostic(behaviors[1].location, "a scenario has at most one `do`", "compose the behaviors with serial: or parallel: under one do")],
                self.text,
            )
        return model.Scenario(
            name=name_ctx.name.getText(),
            actor_type=name_ctx.actorType.getText() if name_ctx.actorType is not None else None,
            actors=tuple(actors),
            behavior=behaviors[0] if behaviors else None,
            location=self.loc(name_ctx.name),
        )

    def behavior(self, ctx: P.BehaviorContext) -> model.Behavior:
        label = ctx.label.getText() if ctx.label is not None else None
        if ctx.composition() is not None:
            comp = ctx.composition()
            return model.Composition(
                operator=comp.compositionOperator().getText(),
                arguments=self.arguments(comp.argumentList()),
                children=tuple(self.behavior(child) for child in comp.behavior()),
                label=label,
                location=self.loc(ctx),
            )
        inv = ctx.invocation()
        return model.Invocation(
            actor=inv.actor.getText() if inv.actor is not None else None,
            action=inv.action.getText(),
            arguments=self.arguments(inv.argumentList()),
            modifiers=tuple(
                model.Modifier(m.name.getText(), self.arguments(m.argumentList()), self.loc(m))
                for m in inv.modifierInvocation()
            ),
            label=label,
            location=self.loc(inv),
        )

    def arguments(self, ctx: P.ArgumentListContext | None) -> tuple[model.Argument, ...]:
        if ctx is None:
            return ()
        result = []
        seen_named = False
        for arg in ctx.argument():
            name = arg.name.getText() if arg.name is not None else None
            if name is None and seen_named:
                raise OscError(
                    [Diagnostic(self.loc(arg), "a positional argument follows a named one", "put positional arguments first")],
                    self.text,
                )
            seen_named = seen_named or name is not None
            result.append(model.Argument(name, self.expression(arg.expression()), self.loc(arg)))
        return tuple(result)

    def expression(self, ctx) -> model.Value:
        location = self.loc(ctx)
        if isinstance(ctx, P.ParenthesisedContext):
            return self.expression(ctx.expression())
        if isinstance(ctx, P.NegationContext):
            inner = self.expression(ctx.expression())
            if isinstance(inner, model.Quantity):
                return model.Quantity(-inner.value, inner.dimension, location)
            raise OscError([Diagnostic(location, "only a number can be negated here")], self.text)
        if isinstance(ctx, P.PhysicalExpressionContext):
            return self.physical(ctx.PhysicalLiteral().getText(), location)
        if isinstance(ctx, P.NumberExpressionContext):
            text = ctx.getText()
            value = float(int(text, 16)) if text.lower().startswith("0x") else float(text)
            return model.Quantity(value, None, location)
        if isinstance(ctx, P.StringExpressionContext):
            return model.Literal(ctx.getText()[1:-1], location)
        if isinstance(ctx, P.BoolExpressionContext):
            return model.Literal(ctx.getText() == "true", location)
        if isinstance(ctx, P.NameExpressionContext):
            return model.Name(ctx.getText(), location)
        if isinstance(ctx, P.RangeExpressionContext):
            return self.range(ctx.rangeLiteral(), location)
        raise OscError([Diagnostic(location, f"unsupported expression {ctx.getText()!r}")], self.text)

    def range(self, ctx: P.RangeLiteralContext, location: SourceLocation) -> model.Range:
        low = self.expression(ctx.low)
        high = self.expression(ctx.high)
        for bound in (low, high):
            if not isinstance(bound, model.Quantity):
                raise OscError([Diagnostic(bound.location, "a range bound must be a number")], self.text)
        if ctx.unit is not None:
            # The paper's spelling `[10..20]m`: the unit after the bracket applies to both bounds.
            unit_loc = self.loc(ctx.unit)
            for bound in (low, high):
                if bound.dimension is not None:
                    raise OscError(
                        [Diagnostic(unit_loc, "a unit after the range, but a bound already has one", "write [10..20]m or [10m..20m], not both")],
                        self.text,
                    )
            dimension, factor = self.unit(ctx.unit.getText(), unit_loc)
            low = model.Quantity(low.value * factor, dimension, low.location)
            high = model.Quantity(high.value * factor, dimension, high.location)
        elif low.dimension != high.dimension:
            raise OscError(
                [Diagnostic(location, f"the range's bounds differ in kind ({low.dimension or 'number'} and {high.dimension or 'number'})")],
                self.text,
            )
        if low.value > high.value:
            low, high = high, low  # the standard accepts either order
        return model.Range(low, high, location)

    def physical(self, text: str, location: SourceLocation) -> model.Quantity:
        number, unit = split_physical_literal(text)
        dimension, factor = self.unit(unit, location)
        return model.Quantity(number * factor, dimension, location)

    def unit(self, unit: str, location: SourceLocation) -> tuple[str, float]:
        if unit not in UNITS:
            known = ", ".join(sorted(UNITS))
            raise OscError([Diagnostic(location, f"unknown unit {unit!r}", f"known units: {known}")], self.text)
        return UNITS[unit]
