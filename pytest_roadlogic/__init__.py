"""pytest-roadlogic: concrete, monitored simulations from OpenSCENARIO DSL scenarios.

The pipeline, one subpackage per stage, data flowing one way:
``frontend`` (OS2 text -> Scenario) -> ``automaton`` (Scenario -> SymbolicAutomaton)
-> ``planning`` (automaton -> Plan, with clingo) -> ``simulation`` (Plan -> Trace, with
CommonRoad and frenetix) -> ``monitor`` (automaton + Trace -> Verdict). ``pipeline`` chains them;
``plugin`` and ``cli`` sit on top.
"""

__version__ = "0.1.0"


def parameters(path, scenario=None, lanes=None):
    """The Hypothesis strategy of a scenario file's logical parameters (dicts of name -> SI value).

    For ordinary ``@given`` tests: ``@given(pytest_roadlogic.parameters("scenarios/overtake.osc"))``;
    pass a sample on as ``run_scenario(scenario, values=sample)``. Imported lazily, so that loading
    the plugin stays cheap.
    """
    from .sampling import parameters as strategy_of

    return strategy_of(path, scenario, lanes)
