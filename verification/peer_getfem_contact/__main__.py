"""``.venv/bin/python -m verification.peer_getfem_contact``: the study's tables (:func:`.cli.main`)."""
import sys

from .cli import main

sys.exit(main())
