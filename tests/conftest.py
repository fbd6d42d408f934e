"""Test configuration.

Being here puts tests/ on sys.path, so tests can import ``public_prompts``. Under CI
(``CI`` set) hypothesis runs derandomized, so a CI run is reproducible; local runs keep
exploring new examples.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
