# With CAROM_LIBRARY set (a build tree's library), test this checkout's
# package; without it, the installed one (make check-python installs the
# wheel into a fresh venv and runs these tests from elsewhere).
import os
import sys

if os.environ.get("CAROM_LIBRARY"):
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
