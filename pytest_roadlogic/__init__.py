"""pytest-roadlogic: concrete, monitored simulations from OpenSCENARIO DSL scenarios.

The pipeline, one subpackage per stage, data flowing one way:
``frontend`` (OS2 text -> Scenario) -> ``automaton`` (Scenario -> SymbolicAutomaton)
-> ``planning`` (automaton -> Plan, with clingo) -> ``simulation`` (Plan -> Trace, with
CommonRoad and frenetix) -> ``monitor`` (automaton + Trace -> Verdict). ``pipeline`` chains them;
``plugin`` and ``cli`` sit on top.
"""

__version__ = "0.1.0"
