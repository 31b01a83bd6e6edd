#!/usr/bin/env python3
"""landyn-envelope without installation: python3 post/landyn_envelope.py --help"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from landyn_post.envelope import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
