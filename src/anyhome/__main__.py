import sys

from anyhome.cli import main

sys.exit(main())
