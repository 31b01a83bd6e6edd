#!/usr/bin/env python3
"""landyn-dispersion without installation: python3 post/landyn_dispersion.py --help"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from landyn_post.dispersion import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
