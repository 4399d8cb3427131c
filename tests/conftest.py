"""Pytest configuration shared by all suites."""

import os

from hypothesis import settings

# Property tests are sized for the 2-core CI budget; LADDERLAB_HYPOTHESIS=thorough runs more examples.
settings.register_profile("ci", max_examples=60, deadline=None)
settings.register_profile("thorough", max_examples=1000, deadline=None)
settings.load_profile(os.environ.get("LADDERLAB_HYPOTHESIS", "ci"))
