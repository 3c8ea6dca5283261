"""The logic every stage shares: the guard algebra (``guards``), the symbolic automaton as data
(``automaton``) and the phase a construct translates into (``phase``).

It sits below the constructs, which translate into it, and below the planner and the monitor,
which read it; building an automaton from a scenario is the ``automaton`` stage's job.
"""
