"""What the benches' summarize.py scripts share: the wall time and peak memory of a run from its
`/usr/bin/time -v` output, the skipped-case notes, and the summary files."""
import json
import os
import re


def timing(path):
    """(wall seconds, peak resident MB) from a /usr/bin/time -v log; None where missing."""
    text = open(path).read() if os.path.exists(path) else ""
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    seconds = (int(wall[1] or 0) * 3600 + int(wall[2]) * 60 + float(wall[3])) if wall else None
    return seconds, (int(rss[1]) / 1024 if rss else None)


def skipped_notes(out):
    """The lines of OUTDIR/skipped.txt (cases whose data is missing)."""
    skipped = os.path.join(out, "skipped.txt")
    return open(skipped).read().splitlines() if os.path.exists(skipped) else []


def write_summary(out, md, payload):
    """OUTDIR/summary.md, OUTDIR/summary.json and the table on standard output."""
    with open(os.path.join(out, "summary.md"), "w") as fp:
        fp.write(md)
    with open(os.path.join(out, "summary.json"), "w") as fp:
        json.dump(payload, fp, indent=2)
    print(md)
