#!/usr/bin/env python3
"""Motion time and the share of moving samples within 5 % of the programmed feed, of Biip dumps
written by `isurface-cli simulate` (64-byte records: line, block, x y z, fb x y z, feed).

usage: feed_share.py DUMP...
"""
import math
import struct
import sys


def measure(path):
    data = open(path, "rb").read()
    header = struct.unpack_from("<I", data, 8)[0]
    cycle = struct.unpack_from("<d", data, 24)[0]  # s
    count = (len(data) - header) // 64
    previous = None
    moving = within = 0
    first = last = None
    for i in range(count):
        record = struct.unpack_from("<II7d", data, header + 64 * i)
        position, feed = record[2:5], record[8]
        if previous is not None:
            speed = math.dist(position, previous) / cycle * 60.0  # mm/min
            if speed > 1.0:
                moving += 1
                within += abs(speed - feed) <= 0.05 * feed
                first = i if first is None else first
                last = i
        previous = position
    span = (last - first + 1) * cycle if first is not None else 0.0
    return span, (100.0 * within / moving if moving else 0.0)


for dump in sys.argv[1:]:
    span, share = measure(dump)
    print(f"{dump}\t{span:.3f} s of motion\t{share:.1f} % within 5 % of the feed")
