"""Typing a scenario's fields: actor or parameter, the built-in type an actor derives from, and the names a message offers."""

from __future__ import annotations

from dataclasses import replace

from .. import model
from ..syntax.standard_library import LazyTable
from . import library
from .environment import ENVIRONMENT_TYPE

# the built-in physical type of each dimension, for a declared alias (velocity for speed)
_BUILTIN_PHYSICAL = LazyTable(lambda _: {dimension: name for name, dimension in library.PHYSICAL_TYPES.items()})


class FieldTyping:
    """A part of the checker (``checker._Checker``): its state is the checker's."""

    def _field_kind(self, item: model.Field) -> str | None:
        location = item.type_location or item.location
        if item.is_list:
            self.error(location, "not supported: list parameters", "use one parameter per value")
            return None
        road_with_lanes = (
            item.type == "road" and item.constraints and all(isinstance(c, model.Keep) for c in item.constraints)
        )
        if item.type in library.ROAD_TYPES or road_with_lanes:
            # a road with its lanes kept (`r1: road with: keep(it.min_lanes == 2)`, the standard's
            # examples) is the scenario's road, as a route is
            # its keep(it.min_lanes ...) / keep(it.max_lanes ...) are lane bounds (road_lanes)
            if item.default is not None or any(not isinstance(c, model.Keep) for c in item.constraints):
                self.error(
                    location,
                    "a road takes no value",
                    "constrain its lanes with keep(it.min_lanes >= n), path_min_driving_lanes(n) or path_max_lanes(n)",
                )
            return "road"
        if item.type in library.MAP_ELEMENT_TYPES:
            if item.constraints or item.default is not None:
                self.error(
                    location,
                    f"not supported: a value or keep() for a {item.type} of the map",
                    "the tool picks it from the map where roads_follow_in_junction names it",
                )
            return "map_element"
        if item.type == ENVIRONMENT_TYPE:
            if item.constraints or item.default is not None:
                self.warning(
                    item.constraints[0].location if item.constraints else item.default.location,
                    f"the fields of the environment {item.name!r} are read but not simulated",
                    "the simulation has no weather, light or geodetic position",
                )
            return "environment"
        if self._actor_base(item.type) is not None:
            if self._driven_as_vehicle(item.type):
                self.warning(
                    location,
                    f"actor type {item.type!r} does not derive from a road user: it is driven as a vehicle",
                    f"declare it as `actor {item.type} inherits vehicle` (or car, truck)",
                )
            return "actor"
        if item.type in library.SCALAR_TYPES or item.type in self.enums:
            return "parameter"
        if item.type in self.physical_types:
            self.error(
                location,
                f"not supported: parameters of type {item.type!r} (a dimension this tool does not model)",
                f"use one of {', '.join(library.PHYSICAL_TYPES)}",
            )
            return None
        if item.type in library.UNSUPPORTED_ACTOR_TYPES:
            self.error(
                location,
                f"not supported: actor type {item.type!r} (the road is a highway)",
                f"use one of {', '.join(library.ACTOR_TYPES)}",
            )
            return None
        if item.type in self.types:
            declared = self.types[item.type]
            if declared.kind == "actor":
                self.error(
                    location,
                    f"actor type {item.type!r} does not derive from a road user",
                    f"declare it as `actor {item.type} inherits vehicle`",
                )
            else:
                # CARLA's examples declare one beside the parameters they use; a use of its fields
                # is an unknown name where it is written
                self.warning(
                    location,
                    f"a parameter of struct type {item.type!r} is read but not used: its fields are not parameters of the scenario",
                    "use scalar parameters (length, speed, ...) for values the scenario depends on",
                )
            return None
        known = [
            *library.ACTOR_TYPES,
            *library.SCALAR_TYPES,
            *sorted(set(self.enums) - set(library.ENUMS)),
            *sorted(self.types),
        ]
        self.error(location, f"unknown type {item.type!r}", self._known("types", known))
        return None

    def _actor_base(self, type_name: str, seen: frozenset[str] = frozenset()) -> str | None:
        """The road user a declared actor type is driven as: the built-in type it derives from
        or, for a bare type or one derived from an abstract actor of the standard library
        (movable_object, physical_object, osc_actor), a vehicle (warned about where used)."""
        if type_name in library.ACTOR_TYPES:
            return type_name
        declared = self.types.get(type_name)
        if declared is None or declared.kind != "actor" or type_name in seen:
            return None
        if self._unrooted(declared):
            return "vehicle"  # a bare actor type (CARLA suites declare `actor Model3`)
        return self._actor_base(declared.parent, seen | {type_name})

    def _unrooted(self, declared: model.TypeDeclaration) -> bool:
        """A declared actor type with no parent, or whose parent is an abstract actor of the library."""
        return declared.parent is None or (
            declared.parent not in self.types and declared.parent in library.ABSTRACT_ACTOR_TYPES
        )

    def _driven_as_vehicle(self, type_name: str) -> bool:
        """Whether a declared actor type reaches no road user and is driven as a vehicle (a warning)."""
        seen: set[str] = set()
        while type_name in self.types and type_name not in seen:
            seen.add(type_name)
            if self._unrooted(self.types[type_name]):
                return True
            type_name = self.types[type_name].parent
        return False

    def _actor_type_names(self) -> list[str]:
        return [*library.ACTOR_TYPES, *(n for n, d in self.types.items() if d.kind == "actor")]

    @staticmethod
    def _known(what: str, names) -> str:
        names = list(dict.fromkeys(names))
        return f"known {what}: {', '.join(names)}" if names else f"there are no {what}"

    def _aliased(self, item: model.Field) -> model.Field:
        """The field with a declared alias of a physical type (``velocity``) read as the built-in one."""
        if item.type not in library.PHYSICAL_TYPES and self.physical_types.get(item.type) in _BUILTIN_PHYSICAL:
            return replace(item, type=_BUILTIN_PHYSICAL[self.physical_types[item.type]])
        return item
