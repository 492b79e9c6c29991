import sys
from pathlib import Path

from hypothesis import settings

sys.path.insert(0, str(Path(__file__).parent))

# The same examples on every run (a property that fails, fails every time, in CI as here), and no
# per-example deadline: the machine is shared, and time is measured in benchmarks/, not in tests.
settings.register_profile("camtool", derandomize=True, deadline=None, print_blob=True)
settings.load_profile("camtool")
