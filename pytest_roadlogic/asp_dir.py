"""Where the answer-set encodings (``.lp`` files) are: inside the package when installed, at the
top of a source checkout otherwise. The one place that knows it (the planner's encodings and the
choice of ways through a map both load from it)."""

from pathlib import Path

ASP_DIR = Path(__file__).resolve().parent / "asp"
if not ASP_DIR.is_dir():  # running from a source checkout: asp/ sits at the top level
    ASP_DIR = Path(__file__).resolve().parent.parent / "asp"
