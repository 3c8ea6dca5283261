"""The syntax of ``.osc`` text, read into the scenario model with a given unit table.

``parse_text`` runs the generated ANTLR parser (through ``IndentingLexer``) and turns the parse
tree into ``model`` dataclasses, reading physical literals with the unit table it is given. It
knows nothing of the standard library, so that the library's own files are read with it; the
parser of every other file (``frontend.syntax.parser``) gives it the library's units. Problems are collected, not printed, and raised together
as one ``OscError``: a user fixing a file wants every mistake in one run, not one per run.

The parser judges spelling only (syntax, units, literal forms). Whether names exist and values have
the right kind is the checker's job, so that ``roadlogic check --syntax-only`` can read files
written for other tools' libraries.
"""

from __future__ import annotations

import ast
import math
import re
from collections.abc import Mapping

from antlr4 import CommonTokenStream, InputStream
from antlr4.error.ErrorListener import ErrorListener
from antlr4.Token import Token
from antlr4.tree.Tree import TerminalNode

from .. import model
from ..errors import Diagnostic, OscError, SourceLocation
from .generated.OpenScenario2Parser import OpenScenario2Parser as P
from .lexer import DEDENT, INDENT, IndentingLexer
from .limits import MAX_MAGNITUDE, check_limits
from .units import SI_UNIT, split_physical_literal

_QUALIFIER = re.compile(r"(?:[A-Za-z_][A-Za-z0-9_]*|\|[^|]*\|)?::")


def unqualified(text: str) -> str:
    """A name as the tool reads it: a 2.1 namespace qualifier (``osc::car``, ``::car``) dropped."""
    return _QUALIFIER.sub("", text) if "::" in text else text


class _CollectingListener(ErrorListener):
    """Collects syntax errors as diagnostics, worded for people rather than for grammar authors."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.diagnostics: list[Diagnostic] = []

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):  # noqa: N802 (ANTLR API)
        kind = getattr(offendingSymbol, "type", None)
        if kind == DEDENT and self.diagnostics:
            return  # the end of a block already in error: a cascade, not news
        if any(d.location.line == line for d in self.diagnostics):
            return  # one syntax error per line is enough to act on
        location = SourceLocation(self.path, line, column + 1)
        if kind == INDENT:
            self.diagnostics.append(
                Diagnostic(location, "unexpected indented block", "is the line before it missing a ':' at its end?")
            )
            return
        text = getattr(offendingSymbol, "text", None)
        shown = {"\n": "end of line", "<EOF>": "end of file", "": "end of block"}.get(text, text)
        message = f"syntax error at {shown!r}: {_shorten(msg)}" if shown else f"syntax error: {_shorten(msg)}"
        hint = None
        if kind == DEDENT or "INDENT" in msg or "DEDENT" in msg:
            hint = "check the indentation: a block starts after a line ending in ':' and is indented further"
        self.diagnostics.append(Diagnostic(location, message, hint))


def _shorten(message: str) -> str:
    """ANTLR lists every expected token; beyond a handful that hides more than it tells."""
    if "expecting {" not in message:
        return message
    head, expected = message.split("expecting {", 1)
    options = [o.strip() for o in expected.rstrip("}").split(",")]
    options = [
        {"INDENT": "an indented block", "DEDENT": "the end of the block", "NEWLINE": "end of line"}.get(o, o)
        for o in options
    ]
    if len(options) > 6:
        options = options[:6] + ["..."]
    return f"{head}expecting one of {', '.join(options)}"


def parse_text(
    text: str, path: str, units: Mapping[str, tuple[str | None, float]], unmodelled: Mapping[str, str] | None = None
) -> model.OscFile:
    """Parse OS2 source text; raise ``OscError`` naming every syntax error found.

    ``units`` is the table physical literals are read with; ``unmodelled`` names the units of
    dimensions the tool does not model (``deg``: angle), refused as such rather than as unknown."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    if text.startswith("\ufeff"):
        text = text[1:]  # a byte-order mark some editors write
    check_limits(text, path)
    try:
        return _parse(text, path, units, unmodelled or {})
    except RecursionError:  # a limit of limits.py should have refused the file first
        raise OscError(
            [
                Diagnostic(
                    SourceLocation(path, 1, 1),
                    "the file nests too deeply for the parser",
                    "flatten its expressions and blocks",
                )
            ]
        ) from None


def _parse(
    text: str, path: str, units: Mapping[str, tuple[str | None, float]], unmodelled: Mapping[str, str]
) -> model.OscFile:
    lexer = IndentingLexer(InputStream(text), path)
    listener = _CollectingListener(path)
    lexer.removeErrorListeners()
    lexer.addErrorListener(listener)
    parser = P(CommonTokenStream(lexer))
    parser.removeErrorListeners()
    parser.addErrorListener(listener)
    tree = parser.oscFile()
    lexer_lines = {d.location.line for d in lexer.diagnostics}
    diagnostics = lexer.diagnostics + [d for d in listener.diagnostics if d.location.line not in lexer_lines]
    if diagnostics:
        raise OscError(_sorted(diagnostics), text)
    builder = _Builder(path, text, units, unmodelled)
    result = builder.file(tree)
    if builder.diagnostics:
        raise OscError(_sorted(builder.diagnostics), text)
    return result


def _sorted(diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    unique = list(dict.fromkeys(diagnostics))
    return sorted(unique, key=lambda d: (d.location.line, d.location.column))


class _Builder:
    """Turns parse-tree contexts into model nodes, collecting spelling problems as it goes."""

    def __init__(
        self, path: str, text: str, units: Mapping[str, tuple[str | None, float]], unmodelled: Mapping[str, str]
    ) -> None:
        self.path = path
        self.text = text
        self.units = units
        self.unmodelled = unmodelled
        self.ignored: list[model.Unsupported] = []  # read and ignored where found, reported with the file
        self.diagnostics: list[Diagnostic] = []
        # cover/record in a field's with:, by field, until its scenario takes them
        self.field_coverage: dict[str, list[model.Coverage]] = {}

    def error(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        self.diagnostics.append(Diagnostic(location, message, hint))

    def loc(self, ctx) -> SourceLocation:
        if isinstance(ctx, Token):
            token = ctx
        elif isinstance(ctx, TerminalNode):
            token = ctx.symbol
        else:
            token = ctx.start
        return SourceLocation(self.path, token.line, token.column + 1)

    # -------------------------------------------------------------- declarations

    def file(self, ctx: P.OscFileContext) -> model.OscFile:
        imports: list[model.Import] = []
        misplaced: list[model.Import] = []
        scenarios: list[model.Scenario] = []
        types: list[model.TypeDeclaration] = []
        enums: list[model.EnumDeclaration] = []
        globals_: list[model.Field] = []
        extensions: list[model.Extension] = []
        unsupported: list[model.Unsupported] = []
        physical_types: list[model.PhysicalTypeDeclaration] = []
        units: list[model.UnitDeclaration] = []
        modifiers: list[model.ModifierDeclaration] = []
        seen_declaration = False
        for child in ctx.getChildren():
            if isinstance(child, P.ImportStatementContext):
                (misplaced if seen_declaration else imports).append(self.import_(child))
            elif isinstance(child, P.DeclarationContext):
                seen_declaration = True
                decl = child.getChild(0)
                if isinstance(decl, P.ScenarioDeclarationContext):
                    scenarios.append(self.scenario(decl))
                elif isinstance(decl, P.PhysicalTypeDeclarationContext):
                    exponents, _, _ = self.si(decl, allow_factor=False)
                    physical_types.append(
                        model.PhysicalTypeDeclaration(self.name(decl.name), exponents, self.loc(decl.name))
                    )
                elif isinstance(decl, P.UnitDeclarationContext):
                    exponents, factor, offset = self.si(decl, allow_factor=True)
                    units.append(
                        model.UnitDeclaration(
                            self.name(decl.name), self.name(decl.type_), exponents, factor, self.loc(decl.name), offset
                        )
                    )
                elif isinstance(decl, (P.ActorDeclarationContext, P.StructDeclarationContext)):
                    declaration, refused = self.type_declaration(decl)
                    types.append(declaration)
                    unsupported.extend(refused)
                elif isinstance(decl, P.EnumDeclarationContext):
                    enums.append(
                        model.EnumDeclaration(
                            self.name(decl.identifier()),
                            tuple(self.name(m.identifier()) for m in decl.enumMember()),
                            self.loc(decl.identifier()),
                        )
                    )
                elif isinstance(decl, P.GlobalDeclarationContext):
                    globals_.extend(self.fields(decl.fieldDeclaration()))
                elif isinstance(decl, P.ExtendDeclarationContext):
                    target = decl.behaviorName()
                    members = [m.scenarioMember() for m in decl.extensionMember() if m.scenarioMember() is not None]
                    added = [
                        *decl.enumMember(),
                        *(m.enumMember() for m in decl.extensionMember() if m.enumMember() is not None),
                    ]
                    if added:  # extend an enum
                        enums.append(
                            model.EnumDeclaration(
                                self.name(target.name),
                                tuple(self.name(m.identifier()) for m in added),
                                self.loc(target.name),
                                extends=True,
                            )
                        )
                    if members or not added:
                        body = self.scenario_body(
                            self.name(target.name), None, self.loc(target.name), members, "scenario"
                        )
                        extensions.append(model.Extension(body.name, body, self.loc(decl)))
                elif (
                    isinstance(decl, P.ModifierDeclarationContext)
                    and decl.OF() is None
                    and all(m.fieldDeclaration() is not None for m in decl.scenarioMember())
                ):
                    # a modifier's signature: its name and parameters (the standard library's
                    # declarations; the checker refuses a file's own with a body)
                    target = decl.behaviorName()
                    owner = self.name(target.actorType) if target.actorType is not None else None
                    parameters = tuple(f for m in decl.scenarioMember() for f in self.fields(m.fieldDeclaration()))
                    modifiers.append(
                        model.ModifierDeclaration(owner, self.name(target.name), self.loc(target.name), parameters)
                    )
                elif isinstance(decl, P.ModifierDeclarationContext):
                    unsupported.append(
                        model.Unsupported(
                            "modifier declarations",
                            self.loc(decl),
                            "use the built-in modifiers (speed, position, lane, ...)",
                        )
                    )
                elif isinstance(decl, P.NamespaceStatementContext):
                    # `namespace demo use std` (2.1): the tool reads the files of a run as one
                    # namespace, the standard library's names in it, so the statement changes no
                    # name it reads (a qualifier ns::name stays refused: qualified_names)
                    pass
                elif isinstance(decl, P.ExportStatementContext):
                    unsupported.append(
                        model.Unsupported(
                            "export", self.loc(decl), "every top-level declaration is visible to an importing file"
                        )
                    )
        unsupported.extend(self.qualified_names(ctx))
        unsupported.extend(self.ignored)
        return model.OscFile(
            path=self.path,
            scenarios=tuple(scenarios),
            source_text=self.text,
            imports=tuple(imports),
            types=tuple(types),
            enums=tuple(enums),
            globals=tuple(globals_),
            extensions=tuple(extensions),
            unsupported=tuple(unsupported),
            misplaced_imports=tuple(misplaced),
            physical_types=tuple(physical_types),
            units=tuple(units),
            modifier_declarations=tuple(modifiers),
        )

    def si(self, ctx, allow_factor: bool) -> tuple[tuple[tuple[str, float], ...], float, float]:
        """The ``SI(m: 1, s: -1, factor: f, offset: o)`` of a type or unit declaration: exponents,
        factor and offset."""
        if self.name(ctx.si) != "SI":
            self.error(self.loc(ctx.si), f"expected SI(...), got {self.name(ctx.si)}(...)", "write SI(m: 1, s: -1)")
        exponents: list[tuple[str, float]] = []
        factor = 1.0
        offset = 0.0
        for argument in self.arguments(ctx.argumentList()):
            value = argument.value  # a signed number is one Quantity (see expression())
            if argument.name is None or not isinstance(value, model.Quantity) or value.dimension is not None:
                self.error(argument.location, "SI() takes base units with plain numbers, e.g. SI(m: 1, s: -1)")
                continue
            if argument.name == "factor" and allow_factor:
                factor = value.value
            elif argument.name == "offset" and allow_factor:
                offset = value.value
            else:
                exponents.append((argument.name, value.value))
        return tuple(exponents), factor, offset

    def qualified_names(self, ctx) -> list[model.Unsupported]:
        """Every 2.1 namespace qualifier (``ns::name``), refused at its place: the tool reads one
        namespace per run, so a qualifier would be ignored rather than honoured. The builder
        reads each name without it (``unqualified``), so that the refusal is the only error."""
        found = []
        stack = [ctx]
        while stack:
            node = stack.pop()
            if isinstance(node, TerminalNode):
                continue
            if isinstance(node, (P.IdentifierContext, P.ExportSpecificationContext)) and node.DOUBLECOLON() is not None:
                text = node.getText()
                found.append(
                    model.Unsupported(
                        f"the namespace qualifier in {text!r}",
                        self.loc(node),
                        "namespaces are not read: drop the qualifier and keep names unique across the files of a run",
                    )
                )
                continue
            stack.extend(node.getChildren())
        return sorted(found, key=lambda u: (u.location.line, u.location.column))

    def import_(self, ctx: P.ImportStatementContext) -> model.Import:
        if ctx.StringLiteral() is not None:
            return model.Import(self.string(ctx.StringLiteral().getText()), True, self.loc(ctx.StringLiteral()))
        return model.Import(unqualified(ctx.dottedName().getText()), False, self.loc(ctx.dottedName()))

    def scenario(self, ctx: P.ScenarioDeclarationContext) -> model.Scenario:
        name_ctx = ctx.behaviorName()
        actor_type = self.name(name_ctx.actorType) if name_ctx.actorType is not None else None
        scenario = self.scenario_body(
            self.name(name_ctx.name), actor_type, self.loc(name_ctx.name), ctx.scenarioMember(), ctx.kind.text
        )
        if ctx.inheritance() is not None:
            inheritance = ctx.inheritance()
            parent = self.name(inheritance.parent.name)
            extra = ()
            if inheritance.condition is not None:
                extra = (model.Unsupported("conditional inheritance", self.loc(inheritance.condition)),)
            from dataclasses import replace

            scenario = replace(scenario, parent=parent, unsupported=scenario.unsupported + extra)
        return scenario

    def scenario_body(self, name, actor_type, location, members, kind) -> model.Scenario:
        fields: list[model.Field] = []
        constraints: list = []
        events: list[model.Event] = []
        methods: list[model.Method] = []
        behaviors: list[model.Behavior] = []
        unsupported: list[model.Unsupported] = []
        modifiers: list[model.Modifier] = []
        coverage: list[model.Coverage] = []
        samples: list[model.SampledVariable] = []
        for member in members:
            item = member.getChild(0)
            if isinstance(item, P.FieldDeclarationContext):
                fields.extend(self.fields(item))
            elif isinstance(item, P.KeepConstraintContext):
                constraints.append(self.keep(item))
            elif isinstance(item, P.RemoveDefaultContext):
                constraints.append(self.remove_default(item))
            elif isinstance(item, P.EventDeclarationContext):
                events.append(self.event(item))
            elif isinstance(item, P.MethodDeclarationContext):
                method = self.method(item)
                methods.append(method)
                if method.external:
                    unsupported.append(
                        model.Unsupported(
                            "an external method",
                            method.location,
                            "this tool runs no code a scenario names, so a call of it is refused; "
                            "write the method as `def name(...) -> type is expression ...`",
                            severity="warning",
                        )
                    )
            elif isinstance(item, P.DoDirectiveContext):
                behaviors.append(self.do_member(item.doMember()))
            elif isinstance(item, P.VariableDeclarationContext) and item.sampleExpression() is not None:
                samples.extend(self.sampled(item))
            elif isinstance(item, P.VariableDeclarationContext):
                unsupported.append(
                    model.Unsupported(
                        "var",
                        self.loc(item),
                        "use a parameter with a range: `x: length with: keep(it in [a..b]m)`; a var is read only as "
                        "`var x: length = sample(expression, @event)` for cover() and record()",
                    )
                )
            elif isinstance(item, P.CoverageDeclarationContext):
                coverage.append(self.coverage(item))
            elif isinstance(item, P.OnDirectiveContext):
                unsupported.append(
                    model.Unsupported("on", self.loc(item), "express the reaction as a serial phase instead")
                )
            elif isinstance(item, P.ModifierInvocationContext):
                modifiers.append(self.modifier(item))
        return model.Scenario(
            name=name,
            actor_type=actor_type,
            actors=(),
            behavior=behaviors[0] if behaviors else None,
            location=location,
            kind=kind,
            fields=tuple(fields),
            constraints=tuple(constraints),
            events=tuple(events),
            methods=tuple(methods),
            behaviors=tuple(behaviors),
            unsupported=tuple(unsupported),
            path=self.path,
            modifiers=tuple(modifiers),
            coverage=tuple(
                sorted(
                    [*coverage, *(c for f in fields for c in self.field_coverage.pop(f.name, ()))],
                    key=lambda c: (c.location.line, c.location.column),
                )
            ),
            samples=tuple(samples),
        )

    def type_declaration(self, ctx) -> tuple[model.TypeDeclaration, tuple[model.Unsupported, ...]]:
        """An actor or struct declaration, and the constructs in it that the checker must refuse."""
        name = self.name(ctx.identifier())
        body = self.scenario_body(name, None, self.loc(ctx.identifier()), ctx.structMember(), "type")
        inheritance = ctx.inheritance()
        parent = self.name(inheritance.parent.name) if inheritance is not None else None
        condition = (
            self.expression(inheritance.condition)
            if inheritance is not None and inheritance.condition is not None
            else None
        )
        kind = "actor" if isinstance(ctx, P.ActorDeclarationContext) else "struct"
        refused = (
            body.unsupported
            + tuple(
                model.Unsupported(
                    "a modifier in a type declaration", m.location, "put it in the with: block of an invocation"
                )
                for m in body.modifiers
            )
            + tuple(
                model.Unsupported(
                    f"{c.kind}() in a type declaration",
                    c.location,
                    f"not collected: write {c.kind}(...) in the scenario, on one of its parameters",
                    severity="warning",
                )
                for c in body.coverage
            )
        )
        declaration = model.TypeDeclaration(
            kind, name, parent, body.fields, body.constraints, body.location, body.methods, condition
        )
        return declaration, refused

    def sampled(self, ctx: P.VariableDeclarationContext) -> list[model.SampledVariable]:
        """``var a, b: type = sample(expression, @event)``: one sampled variable per name."""
        sample = ctx.sampleExpression()
        expression = self.expression(sample.expression(0))
        event = self.event_specification(sample.eventSpecification())
        declared = ctx.typeDeclarator()
        type_name = (
            self.name(declared.identifier()) if declared is not None and declared.identifier() is not None else None
        )
        return [
            model.SampledVariable(self.name(ident), type_name, expression, event, self.loc(ident))
            for ident in ctx.identifier()
        ]

    def coverage(self, ctx: P.CoverageDeclarationContext, field: str | None = None) -> model.Coverage:
        """``cover(...)``/``record(...)``, its arguments as written (the checker reads them:
        ``semantics.coverage``); in a field's ``with:``, ``field`` names the field."""
        return model.Coverage(ctx.getChild(0).getText(), self.arguments(ctx.argumentList()), self.loc(ctx), field)

    def fields(self, ctx: P.FieldDeclarationContext) -> list[model.Field]:
        declarator = ctx.typeDeclarator()
        type_name = self.name(declarator.identifier())
        default = self.expression(ctx.defaultValue) if ctx.defaultValue is not None else None
        result = []
        for ident in ctx.identifier():
            name = self.name(ident)
            constraints = []
            for constraint in ctx.fieldConstraint():
                item = constraint.getChild(0)
                if isinstance(item, P.KeepConstraintContext):
                    constraints.append(self.keep(item, subject=name))
                elif isinstance(item, P.CoverageDeclarationContext):
                    if ident is ctx.identifier()[0]:
                        self.field_coverage.setdefault(name, []).append(self.coverage(item, name))
                else:
                    constraints.append(self.remove_default(item))
            result.append(
                model.Field(
                    name=name,
                    type=type_name,
                    default=default,
                    constraints=tuple(constraints),
                    location=self.loc(ident),
                    is_list=declarator.LIST() is not None,
                    type_location=self.loc(declarator),
                )
            )
        return result

    def keep(self, ctx: P.KeepConstraintContext, subject: str | None = None) -> model.Keep:
        strength = "default" if ctx.strength is not None and ctx.strength.text == "default" else "hard"
        return model.Keep(self.expression(ctx.expression()), strength, self.loc(ctx), subject)

    def remove_default(self, ctx: P.RemoveDefaultContext) -> model.RemoveDefault:
        return model.RemoveDefault(self.expression(ctx.expression()), self.loc(ctx))

    def event(self, ctx: P.EventDeclarationContext) -> model.Event:
        spec = self.event_specification(ctx.eventSpecification()) if ctx.eventSpecification() is not None else None
        return model.Event(self.name(ctx.identifier()), spec, self.loc(ctx.identifier()))

    def event_specification(self, ctx: P.EventSpecificationContext) -> model.EventSpecification:
        if ctx.AT_SIGN() is not None:
            condition = self.expression(ctx.expression()) if ctx.expression() is not None else None
            return model.EventReference(unqualified(ctx.dottedName().getText()), condition, self.loc(ctx))
        return self.expression(ctx.expression())

    def method(self, ctx: P.MethodDeclarationContext) -> model.Method:
        parameters = []
        if ctx.parameterList() is not None:
            for p in ctx.parameterList().parameter():
                default = self.expression(p.expression()) if p.expression() is not None else None
                parameters.append(
                    model.Field(
                        self.name(p.identifier()), unqualified(p.typeDeclarator().getText()), default, (), self.loc(p)
                    )
                )
        body = self.expression(ctx.expression()) if ctx.expression() is not None else None
        return_type = unqualified(ctx.typeDeclarator().getText()) if ctx.typeDeclarator() is not None else None
        return model.Method(
            self.name(ctx.identifier()),
            tuple(parameters),
            return_type,
            body,
            ctx.EXTERNAL() is not None,
            self.loc(ctx.identifier()),
        )

    # -------------------------------------------------------------- behavior

    def do_member(self, ctx: P.DoMemberContext) -> model.Behavior:
        label = self.name(ctx.label) if ctx.label is not None else None
        location = self.loc(ctx)
        if ctx.composition() is not None:
            comp = ctx.composition()
            return model.Composition(
                operator=comp.compositionOperator().getText(),
                arguments=self.arguments(comp.argumentList()),
                children=tuple(self.do_member(child) for child in comp.doMember()),
                label=label,
                location=location,
            )
        if ctx.waitDirective() is not None:
            return model.Wait(self.event_specification(ctx.waitDirective().eventSpecification()), label, location)
        if ctx.emitDirective() is not None:
            emit = ctx.emitDirective()
            return model.Emit(self.name(emit.identifier()), self.arguments(emit.argumentList()), label, location)
        if ctx.callDirective() is not None:
            return model.CallStatement(self.expression(ctx.callDirective().expression()), label, location)
        return self.invocation(ctx.behaviorInvocation(), label)

    def invocation(self, ctx: P.BehaviorInvocationContext, label: str | None) -> model.Invocation:
        parts = [self.name(i) for i in ctx.target.identifier()]
        modifiers: list[model.Modifier] = []
        constraints: list = []
        until = None
        for member in ctx.behaviorWithMember():
            item = member.getChild(0)
            if isinstance(item, P.ModifierInvocationContext):
                modifiers.append(self.modifier(item))
            elif isinstance(item, P.KeepConstraintContext):
                constraints.append(self.keep(item, subject="it"))
            elif isinstance(item, P.RemoveDefaultContext):
                constraints.append(self.remove_default(item))
            elif isinstance(item, P.UntilDirectiveContext):
                until = self.event_specification(item.eventSpecification())
        return model.Invocation(
            actor=".".join(parts[:-1]) or None,
            action=parts[-1],
            arguments=self.arguments(ctx.argumentList()),
            modifiers=tuple(modifiers),
            label=label,
            location=self.loc(ctx),
            constraints=tuple(constraints),
            until=until,
        )

    def modifier(self, ctx: P.ModifierInvocationContext) -> model.Modifier:
        names = [self.name(i) for i in ctx.target.identifier()]
        return model.Modifier(
            names[-1],
            self.arguments(ctx.argumentList()),
            self.loc(ctx.target.identifier()[-1]),
            actor=".".join(names[:-1]) or None,
            label=self.name(ctx.label) if ctx.label is not None else None,
        )

    def arguments(self, ctx: P.ArgumentListContext | None) -> tuple[model.Argument, ...]:
        if ctx is None:
            return ()
        result = []
        # a positional argument after a named one (which public files write) is read as the first
        # parameter no argument names (library.bind)
        for arg in ctx.argument():
            name = self.name(arg.name) if arg.name is not None else None
            result.append(model.Argument(name, self.expression(arg.expression()), self.loc(arg)))
        return tuple(result)

    # -------------------------------------------------------------- expressions

    def expression(self, ctx) -> model.Expression:
        location = self.loc(ctx)
        if isinstance(ctx, P.PrimaryExpressionContext):
            return self.primary(ctx.primary())
        if isinstance(ctx, P.MemberAccessContext):
            base = self.expression(ctx.expression())
            if isinstance(base, model.Name) and base.enum is None:
                return model.Name(f"{base.name}.{self.name(ctx.identifier())}", base.location)
            self.error(location, "a field can only be read from a name, e.g. it.speed or v1.length")
            return base
        if isinstance(ctx, (P.TypeTestContext, P.ElementAccessContext, P.ConditionalContext)):
            operands = [self.expression(e) for e in ctx.getTypedRuleContexts(P.ExpressionContext)]
            if isinstance(ctx, P.TypeTestContext) and ctx.op.type == P.AS:
                # ``x.as(T)``: x seen as a T; on a name it is that name (``ego.as(vehicle).speed``
                # reads ego's speed); the tool's actors have one type each: nothing to convert
                if isinstance(operands[0], model.Name) and operands[0].enum is None:
                    return operands[0]
            # read, never evaluated: a call named after the construct (library.UNSUPPORTED_EXPRESSIONS)
            if isinstance(ctx, P.TypeTestContext):
                function = "is" if ctx.op.type == P.IS else "as"
            else:
                function = "[]" if isinstance(ctx, P.ElementAccessContext) else "?:"
            return model.Call(function, tuple(model.Argument(None, e, location) for e in operands), location)
        if isinstance(ctx, P.CallContext):
            function = self.expression(ctx.expression())
            arguments = self.arguments(ctx.argumentList())
            if not isinstance(function, model.Name):
                self.error(location, "only a named function can be called")
                return function
            if function.name == "range" and len(arguments) == 2 and all(a.name is None for a in arguments):
                return self.range(arguments[0].value, arguments[1].value, None, location)
            return model.Call(function.name, arguments, location)
        if isinstance(ctx, P.UnaryContext):
            operand = self.expression(ctx.expression())
            if ctx.op.text == "+":
                return operand
            if isinstance(operand, model.Quantity):
                return model.Quantity(-operand.value, operand.dimension, location)
            return model.Unary("-", operand, location)
        if isinstance(ctx, P.LogicalNotContext):
            return model.Unary("not", self.expression(ctx.expression()), location)
        if isinstance(ctx, (P.MultiplicativeContext, P.AdditiveContext, P.RelationContext)):
            left, right = ctx.expression()
            return model.Binary(ctx.op.text, self.expression(left), self.expression(right), self.loc(ctx.op))
        if isinstance(ctx, (P.LogicalAndContext, P.LogicalOrContext, P.ImplicationContext)):
            left, right = ctx.expression()
            operator = {P.LogicalAndContext: "and", P.LogicalOrContext: "or"}.get(type(ctx), "=>")
            return model.Binary(operator, self.expression(left), self.expression(right), location)
        self.error(location, f"unsupported expression {ctx.getText()!r}")
        return model.Literal(ctx.getText(), location)

    def primary(self, ctx) -> model.Expression:
        location = self.loc(ctx)
        if isinstance(ctx, P.ParenthesisedContext):
            return self.expression(ctx.expression())
        if isinstance(ctx, P.PhysicalLiteralContext):
            return self.physical(ctx.getText(), location)
        if isinstance(ctx, P.NumberLiteralContext):
            text = ctx.getText()
            value = float(int(text, 16)) if text.lower().startswith("0x") else float(text)
            return model.Quantity(value, None, location)
        if isinstance(ctx, P.StringLiteralContext):
            return model.Literal(self.string(ctx.getText()), location)
        if isinstance(ctx, P.BoolLiteralContext):
            return model.Literal(ctx.getText() == "true", location)
        if isinstance(ctx, P.NamePrimaryContext):
            name = self.name(ctx.identifier())
            if name in ("inf", "nan"):
                return model.Quantity(math.inf if name == "inf" else math.nan, None, location)
            return model.Name(name, location)
        if isinstance(ctx, P.EnumValueContext):
            return model.Name(self.name(ctx.member), location, enum=self.name(ctx.enumType))
        if isinstance(ctx, P.ListLiteralContext):
            return model.ListValue(tuple(self.expression(e) for e in ctx.expression()), location)
        if isinstance(ctx, P.RangePrimaryContext):
            literal = ctx.rangeLiteral()
            unit = literal.unit
            return self.range(self.expression(literal.low), self.expression(literal.high), unit, location)
        self.error(location, f"unsupported expression {ctx.getText()!r}")
        return model.Literal(ctx.getText(), location)

    def range(self, low, high, unit_token, location: SourceLocation) -> model.Expression:
        if unit_token is None and not (isinstance(low, model.Quantity) and isinstance(high, model.Quantity)):
            # bounds computed from parameters (``[min_gap..max_gap]``): the range operator, evaluated
            # with the parameters' values (values.evaluate)
            return model.Binary("..", low, high, location)
        for bound in (low, high):
            if not isinstance(bound, model.Quantity):
                self.error(
                    bound.location, "a range bound must be a number, with its unit", "write [10m..20m] or [10..20]m"
                )
                return model.Literal("<bad range>", location)
        if unit_token is not None:
            # The paper's spelling `[10..20]m`: the unit after the bracket applies to both bounds.
            unit_loc = SourceLocation(self.path, unit_token.line, unit_token.column + 1)
            if low.dimension is not None or high.dimension is not None:
                self.error(
                    unit_loc,
                    "a unit after the range, but a bound already has one",
                    "write [10..20]m or [10m..20m], not both",
                )
                return model.Literal("<bad range>", location)
            dimension, to_si = self.unit_conversion(unit_token.text, unit_loc)
            low = model.Quantity(to_si(low.value), dimension, low.location)
            high = model.Quantity(to_si(high.value), dimension, high.location)
            for bound in (low, high):
                self.bounded(bound.value, dimension, bound.location)
        elif low.dimension != high.dimension:
            self.error(
                location,
                f"the range's bounds differ in kind ({low.dimension or 'number'} and {high.dimension or 'number'})",
                "give both bounds a unit of the same kind",
            )
            return model.Literal("<bad range>", location)
        if low.value > high.value:
            # an empty interval: no value lies in it; most likely the bounds were swapped
            self.error(
                location,
                "an empty range: its first bound is above its second",
                "write the smaller bound first, e.g. [10..20]m",
            )
            return model.Literal("<bad range>", location)
        return model.Range(low, high, location)

    def physical(self, text: str, location: SourceLocation) -> model.Quantity:
        number, unit = split_physical_literal(text)
        dimension, to_si = self.unit_conversion(unit, location)
        value = to_si(number)
        self.bounded(value, dimension, location)
        return model.Quantity(value, dimension, location)

    def bounded(self, value: float, dimension: str | None, location: SourceLocation) -> None:
        """Refuse a physical value past MAX_MAGNITUDE at its place, before the planner reads it."""
        if dimension is not None and not abs(value) <= MAX_MAGNITUDE:
            unit = SI_UNIT.get(dimension, "")
            self.error(
                location,
                f"{value:g} {unit} is past what the tool computes with: at most {MAX_MAGNITUDE:g} {unit}",
                "write a value a road scenario can have (1e6 m is 1,000 km, 1e6 s 11 days)",
            )

    def unit_conversion(self, unit: str, location: SourceLocation):
        """The unit's dimension and the function from a number in it to SI: times its factor, plus
        its offset when it has one (a temperature's zero)."""
        dimension, factor, *offset = self.unit(unit, location)
        zero = offset[0] if offset else 0.0
        return dimension, lambda number: number * factor + zero

    def unit(self, unit: str, location: SourceLocation) -> tuple[str | None, float]:
        try:
            return self.units[unit]
        except KeyError:
            known = ", ".join(sorted(self.units))
            unmodelled = self.unmodelled.get(unit)
            if unmodelled is not None:
                self.error(
                    location,
                    f"not supported: unit {unit!r} (of {unmodelled}, a dimension this tool does not model)",
                    f"the pipeline computes lengths, times, speeds and accelerations; known units: {known}",
                )
            else:
                self.error(
                    location,
                    f"unknown unit {unit!r}",
                    f"known units: {known}; a file may declare its own: unit {unit} of length is SI(m: 1, factor: ...)",
                )
            return None, 1.0

    def string(self, text: str) -> str:
        for quote in ('"""', "'''"):
            if text.startswith(quote) and text.endswith(quote) and len(text) >= 6:
                return text[3:-3]
        try:
            return ast.literal_eval(text)
        except (ValueError, SyntaxError):
            return text[1:-1]

    def name(self, ctx) -> str:
        text = unqualified(ctx.getText() if hasattr(ctx, "getText") else ctx.text)
        if text.startswith("|") and text.endswith("|"):
            return text[1:-1]
        return text
