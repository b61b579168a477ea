"""What touching fresh memory costs on this machine (results.md, "The first
frame per million cells").

    /usr/bin/python3 Documentation/datasets/first_touch.py [--gigabytes G] [--times N]

Fills G gigabytes with np.ones N times in one process (deleting the array
between), printing the milliseconds of each fill and of a second write over
the same array. On a virtual machine whose guest has not touched that much
memory recently, the first fill pays the host's first touch.
"""
import argparse
import time

import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gigabytes", type=float, default=1.0)
    parser.add_argument("--times", type=int, default=3)
    args = parser.parse_args()
    count = int(args.gigabytes * 1e9 / 8)
    for _ in range(args.times):
        start = time.perf_counter()
        values = np.ones(count)
        filled = time.perf_counter()
        values[:] = 2.0
        written = time.perf_counter()
        print("fill %.1f GB: %.0f ms, write it again: %.0f ms"
              % (args.gigabytes, 1000 * (filled - start), 1000 * (written - filled)), flush=True)
        del values


if __name__ == "__main__":
    main()
