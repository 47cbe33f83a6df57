"""python3 -m smoothsteer.campaign SPEC.yaml --out DIR: runs a campaign and writes its report."""
import sys

from . import main

sys.exit(main())
