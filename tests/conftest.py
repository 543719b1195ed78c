"""Hypothesis profiles: CI (CI=true) runs a fixed, derandomised set of examples so a landing never
depends on the luck of the draw; locally every run explores new examples."""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
