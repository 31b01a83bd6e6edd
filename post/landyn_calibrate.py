#!/usr/bin/env python3
"""landyn-calibrate without installation: python3 post/landyn_calibrate.py --help"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from landyn_post.calibrate import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
