#!/usr/bin/env python3
"""Seeds for fuzz_time_history's reader shapes of issue 13 (title lines,
unit suffixes, ';' with decimal commas, --decimal-comma between blanks, a
restart under keep-last, --skip-rows), written into the committed corpus as
<sha1 of the bytes>. Layout (fuzz_time_history.cpp): 4 option bytes, then the
file; byte 3 bit 3 decimal_comma, bit 4 keep_last, bits 5-7 skip_rows.

    python3 tests/fuzz/tools/make_time_history_seeds.py tests/fuzz/corpus/time_history
"""
import hashlib
import os
import sys

SEEDS = [
    (bytes([0, 0, 0, 0]), b"FRICTION MODEL RUN 42\ntime_s;x_m;v_mps\n0;0;0\n0,5;0,1;0,2\n1;0,3;-0,25\n"),
    (bytes([0, 0, 0, 8]), b"t v\n0 0,5\n1,25 -2\n2,5 1e-3\n"),
    (bytes([0, 0, 0, 16]), b"t,v,x\n0,0,0\n1,1,1\n2,2,2\n1.5,5,5\n2.5,6,6\n"),
    (bytes([0, 0, 0, 32]), b"RUN 42 OF 50\nt,v\n0,0\n1,1\n"),
]

out = sys.argv[1]
for head, body in SEEDS:
    data = head + body
    with open(os.path.join(out, hashlib.sha1(data).hexdigest()), "wb") as f:
        f.write(data)
