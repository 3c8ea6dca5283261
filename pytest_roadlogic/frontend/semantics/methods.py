"""Expression methods: ``def name(p: T, ...) -> R is expression E`` used as a value.

A method whose body is an expression is a pure function of its arguments, so a call of it is
replaced, before the scenario is checked, by its body with each parameter bound to its argument.
Every later stage then sees an ordinary expression: the checker types it where it stands, the
sampler and the planner read its value, and an error inside the body points at the body's line.

What a call may name, as the standard and CARLA's runner write it:
- ``T.name(...)``: a method of the struct or actor type ``T`` (CARLA's ``speeds.compute(x:, y:)``);
- ``x.name(...)``: a method of the type of ``x``, a field of the scenario or a global; the body's
  names that are fields of that type read as ``x``'s (``x.field``);
- ``name(...)``: a method the scenario itself declares (or inherits); the body's other names are
  the scenario's.

Binding: arguments by position, then by name; a parameter left out takes its default. A method
declared ``is undefined`` has no value, and an external one would run code a scenario names: a call
of either is refused at the call. A call whose name no declared method answers to is left for the
checker (the library's functions: ``elapsed``, ``sample``, ``space_gap``, ...).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from .. import model
from ..errors import Diagnostic, SourceLocation
from .invocation import substitute_names

# methods inside methods: deeper than this is a method that calls itself
MAX_DEPTH = 16
# nodes of one call's expression once its methods are inlined: a method that uses its argument
# several times, called within itself a few levels deep, grows without bound (4 uses, 16 levels:
# 4^16 nodes), and every later stage walks the expression
MAX_NODES = 10_000
# calls inlined in one scenario: past this each further call is refused, so that a method that
# calls another several times, a few levels deep, cannot make the inlining itself take forever
MAX_CALLS = 10_000


@dataclasses.dataclass(frozen=True)
class Methods:
    """The methods a scenario's calls may name: each type's (inherited ones included) and the
    scenario's own; ``field_types``: the type of each field and global a call may be made on."""

    of_type: Mapping[str, Mapping[str, model.Method]]
    own: Mapping[str, model.Method]
    field_types: Mapping[str, str]
    type_fields: Mapping[str, tuple[str, ...]]
    structs: frozenset[str] = frozenset()

    @classmethod
    def declared(
        cls,
        types: Mapping[str, model.TypeDeclaration],
        own: tuple[model.Method, ...],
        fields: tuple[model.Field, ...],
    ) -> Methods:
        """The methods of ``types`` (a type's parent's first, its own over them), ``own`` and the
        fields calls may be made on."""
        of_type: dict[str, dict[str, model.Method]] = {}
        type_fields: dict[str, tuple[str, ...]] = {}
        for name in types:
            chain: list[model.TypeDeclaration] = []
            current = types.get(name)
            while current is not None and current not in chain:
                chain.append(current)
                current = types.get(current.parent) if current.parent else None
            of_type[name] = {m.name: m for declared in reversed(chain) for m in declared.methods}
            type_fields[name] = tuple(f.name for declared in chain for f in declared.fields)
        structs = frozenset(name for name, declared in types.items() if declared.kind == "struct")
        return cls(of_type, {m.name: m for m in own}, {f.name: f.type for f in fields}, type_fields, structs)

    @property
    def none(self) -> bool:
        """Whether no type and not the scenario declare any method: then no call can name one."""
        return not self.own and not any(self.of_type.values())

    def resolve(self, function: str) -> tuple[model.Method, str | None, str | None] | None:
        """The method ``function`` names, the type that declares it (None for the scenario's own)
        and the field it is called on (None when called on the type or the scenario)."""
        head, dot, rest = function.partition(".")
        if not dot:
            method = self.own.get(head)
            return (method, None, None) if method is not None else None
        if "." in rest:
            return None
        if head in self.of_type:
            method = self.of_type[head].get(rest)
            return (method, head, None) if method is not None else None
        type_name = self.field_types.get(head)
        if type_name in self.of_type:
            method = self.of_type[type_name].get(rest)
            return (method, type_name, head) if method is not None else None
        return None

    def unknown_method(self, function: str) -> tuple[str, tuple[str, ...]] | None:
        """``(type, its methods)`` when ``function`` is ``T.m`` or ``x.m`` on a struct type that
        declares methods but none named ``m``; None otherwise (an actor has the library's methods
        too: ``ego.space_gap(npc)``)."""
        head, dot, rest = function.partition(".")
        if not dot or "." in rest:
            return None
        type_name = head if head in self.of_type else self.field_types.get(head)
        if type_name not in self.structs:
            return None
        methods = self.of_type.get(type_name or "", {})
        if methods and rest not in methods:
            return type_name, tuple(sorted(methods))
        return None


@dataclasses.dataclass
class Inlined:
    """What inlining gave: the node with its calls replaced, the problems found at the calls, and
    where the calls that were refused stand (their value is unknown: the checker says no more of it)."""

    node: object
    problems: list[Diagnostic] = dataclasses.field(default_factory=list)
    refused: set[SourceLocation] = dataclasses.field(default_factory=set)
    calls: int = 0  # calls inlined so far (MAX_CALLS)


def inline_methods(node, methods: Methods) -> Inlined:
    """``node`` (a model node or a tuple of them) with every call of an expression method replaced
    by the method's body bound to the call's arguments."""
    result = Inlined(node)
    if not methods.none:  # most files declare none: their trees are left as they are, unwalked
        result.node = _Inliner(methods, result).inline(node, ())
    return result


def inline_scenario(scenario: model.Scenario, methods: Methods) -> Inlined:
    """``inline_methods`` of a scenario, whose member statements that call an expression method
    (CARLA's ``speeds.compute(x: 2, y: 3)`` on a line of its own) are checked as calls and dropped,
    with a warning: a pure method's value that nothing uses changes nothing."""
    result = inline_methods(scenario, methods)
    if methods.none:
        return result
    inliner = _Inliner(methods, result)
    kept = []
    for modifier in result.node.modifiers:
        function = f"{modifier.actor}.{modifier.name}" if modifier.actor else modifier.name
        if methods.resolve(function) is None:
            kept.append(modifier)
            continue
        inliner.inline(model.Call(function, modifier.arguments, modifier.location), ())
        result.problems.append(
            Diagnostic(
                modifier.location,
                f"the value of {function}(...) is not used: the call is read and changes nothing",
                "give the value a name (x: type = ...) where the scenario uses it, or remove the line",
                "warning",
            )
        )
    if len(kept) < len(result.node.modifiers):
        result.node = dataclasses.replace(result.node, modifiers=tuple(kept))
    return result


@dataclasses.dataclass
class _Inliner:
    methods: Methods
    result: Inlined

    def refuse(self, call: model.Call, location: SourceLocation, message: str, hint: str) -> model.Call:
        """``call`` left as it is, with the problem said once for its place."""
        if call.location not in self.result.refused:
            self.result.problems.append(Diagnostic(location, message, hint))
            self.result.refused.add(call.location)
        return call

    def inline(self, node, stack: tuple[str, ...]):
        """``node`` with its calls inlined; ``node`` itself where nothing in it changes."""
        if isinstance(node, tuple):
            items = tuple(self.inline(item, stack) for item in node)
            return node if all(a is b for a, b in zip(items, node, strict=True)) else items
        if isinstance(node, model.Method) or not dataclasses.is_dataclass(node) or isinstance(node, type):
            return node  # a declaration's body is inlined where it is called, with its arguments
        if isinstance(node, model.Call):
            return self.call(node, stack)
        changes = {}
        for field in dataclasses.fields(node):
            value = getattr(node, field.name)
            if isinstance(value, tuple) or (dataclasses.is_dataclass(value) and not isinstance(value, type)):
                inlined = self.inline(value, stack)
                if inlined is not value:
                    changes[field.name] = inlined
        return dataclasses.replace(node, **changes) if changes else node

    def call(self, call: model.Call, stack: tuple[str, ...]):
        if call.location in self.result.refused:
            return call  # refused where it stands: said once, not again inside a body that uses it
        arguments = self.inline(call.arguments, stack)
        if arguments is not call.arguments:
            call = dataclasses.replace(call, arguments=arguments)
        found = self.methods.resolve(call.function)
        if found is None:
            unknown = self.methods.unknown_method(call.function)
            if unknown is None:
                return call
            type_name, known = unknown
            name = call.function.rpartition(".")[2]
            return self.refuse(
                call, call.location, f"type {type_name!r} has no method {name!r}", f"its methods: {', '.join(known)}"
            )
        method, type_name, receiver = found
        if method.external:
            return self.refuse(
                call,
                call.location,
                f"not supported: a call of the external method {method.name!r}",
                "this tool runs no code a scenario names; write the method as `def name(...) -> type is expression ...`",
            )
        if method.body is None:
            return self.refuse(
                call,
                call.location,
                f"method {method.name!r} is declared `is undefined`: it has no value here",
                f"give it a body on line {method.location.line}: `is expression ...`",
            )
        self.result.calls += 1
        if self.result.calls > MAX_CALLS:
            return self.refuse(
                call,
                call.location,
                f"more than {MAX_CALLS:,} method calls to inline in this scenario",
                "write the value out, or call the methods fewer times within each other",
            )
        key = f"{type_name or ''}.{method.name}"
        if key in stack:
            return self.refuse(
                call,
                call.location,
                f"method {method.name!r} calls itself",
                "a method's value must not depend on itself; write the value out",
            )
        if len(stack) >= MAX_DEPTH:
            return self.refuse(
                call,
                call.location,
                f"methods call each other more than {MAX_DEPTH} deep here",
                "write the value out, or call fewer methods within each other",
            )
        bound = self.bind(call, method)
        if bound is None:
            return call
        if receiver is not None:
            for name in self.methods.type_fields.get(type_name or "", ()):
                bound.setdefault(name, model.Name(f"{receiver}.{name}", call.location))
        inlined = self.inline(substitute_names(method.body, bound), (*stack, key))
        if tree_size(inlined) > MAX_NODES:
            return self.refuse(
                call,
                call.location,
                f"the call of method {method.name!r} expands to an expression of more than {MAX_NODES:,} terms",
                "write the value out, or call the methods fewer times within each other",
            )
        return inlined

    def bind(self, call: model.Call, method: model.Method) -> dict[str, model.Expression] | None:
        """Each parameter's expression (its argument's, else its default); None after a problem."""
        names = [p.name for p in method.parameters]
        listed = f"its parameters: {', '.join(names) or 'none'}"
        bound: dict[str, model.Expression] = {}
        positional = [a for a in call.arguments if a.name is None]
        if len(positional) > len(names):
            plural = "s" * (len(names) != 1)
            self.refuse(
                call,
                call.location,
                f"method {method.name!r} takes {len(names)} argument{plural}, the call gives {len(positional)}",
                listed,
            )
            return None
        for name, argument in zip(names, positional, strict=False):
            bound[name] = argument.value
        for argument in call.arguments:
            if argument.name is None:
                continue
            if argument.name not in names:
                self.refuse(
                    call, argument.location, f"method {method.name!r} has no parameter {argument.name!r}", listed
                )
                return None
            if argument.name in bound:
                self.refuse(call, argument.location, f"parameter {argument.name!r} is given twice", "give it once")
                return None
            bound[argument.name] = argument.value
        for parameter in method.parameters:
            if parameter.name in bound:
                continue
            if parameter.default is None:
                self.refuse(
                    call,
                    call.location,
                    f"the call of method {method.name!r} gives no {parameter.name!r}",
                    f"give it: {method.name}({parameter.name}: ...)",
                )
                return None
            bound[parameter.name] = parameter.default
        return bound


def tree_size(node, sizes: dict[int, int] | None = None) -> int:
    """The nodes of ``node`` read as a tree (a shared subexpression counted each time it is used),
    counted in time linear in the distinct nodes: inlining shares an argument wherever the body
    uses it, so the tree may be exponentially larger than the objects that make it."""
    sizes = {} if sizes is None else sizes
    key = id(node)
    if key in sizes:
        return sizes[key]
    if isinstance(node, tuple):
        size = sum(tree_size(item, sizes) for item in node)
    elif dataclasses.is_dataclass(node) and not isinstance(node, type):
        size = 1 + sum(tree_size(getattr(node, field.name), sizes) for field in dataclasses.fields(node))
    else:
        size = 0
    sizes[key] = size
    return size
