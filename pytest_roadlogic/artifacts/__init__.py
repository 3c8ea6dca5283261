"""What a run leaves for people and other tools: one module per output.

``writer.write_artifacts`` writes them all for one run (plan, trace, CommonRoad scenario, plot,
animation, verdict); ``plot``, ``animation`` and ``commonroad`` each write one; ``files.write_text``
writes any file atomically (a temporary name renamed into place). A new output format is a module
here and a line in ``write_artifacts``. Importing this package imports none of them.
"""
