#!/usr/bin/python3
"""Table of a run-peers.sh output directory: OUTDIR/summary.md, OUTDIR/summary.json, stdout.

usage: /usr/bin/python3 summarize.py OUTDIR [TIMEOUT_SECONDS]
Per case (OUTDIR/cases.txt: name|cloud|reference) and tool (OUTDIR/commands.txt: name|tool|command)
it reads NAME.TOOL.rc, .time (/usr/bin/time -v), .load (1-minute load at the start), .err and
.score.json (score.py). Nothing is judged: the table only puts the numbers side by side.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from summary import skipped_notes, timing, write_summary  # noqa: E402




def run(out, name, tool, command, timeout):
    base = os.path.join(out, f"{name}.{tool}")
    read = lambda ext: open(base + ext).read().strip() if os.path.exists(base + ext) else None
    rc = read(".rc")
    rc = int(rc) if rc else None
    wall, rss = timing(base + ".time")
    err = [l.strip() for l in (read(".err") or "").splitlines()]
    first_error = next((l for l in err if "error" in l.lower()), next((l for l in err if l), ""))
    status = ("ok" if rc == 0 else "not run" if rc is None
              else f"timeout {timeout} s" if rc == 124 else f"exit {rc}: {first_error}")
    r = {"cloud": name, "tool": tool, "command": command, "status": status, "exit": rc, "wall_s": wall,
         "peak_rss_mb": rss, "load_1min_at_start": float(read(".load")) if read(".load") else None}
    score = read(".score.json")
    if score:
        r.update(json.loads(score))
    elif rc == 0:
        r["status"] = "ok, no surface scored"
    return r


def fmt(v, spec=""):
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float) and v.is_integer() and not spec:
        return str(int(v))
    return format(v, spec)


def table(rows):
    sampled = any("sampled_chamfer" in r for r in rows)
    head = ["cloud", "tool", "wall s", "peak MB", "Chamfer", "Hausdorff", "pieces", "genus", "closed"]
    head += ["Chamfer, area samples"] if sampled else []
    head += ["load", "status"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        closed = r.get("closed")
        if closed is False:  # say why it is not closed
            closed = f"no ({r['boundary_edges']} bnd" + (f", {r['nonmanifold_edges']} nm)" if r["nonmanifold_edges"] else ")")
        cells = [r["cloud"], r["tool"], fmt(r["wall_s"], ".1f"), fmt(r["peak_rss_mb"], ".0f"),
                 fmt(r.get("chamfer"), ".3g"), fmt(r.get("hausdorff"), ".3g"), fmt(r.get("pieces")),
                 fmt(r.get("genus")), fmt(closed)]
        cells += [fmt(r.get("sampled_chamfer"), ".3g")] if sampled else []
        cells += [fmt(r["load_1min_at_start"], ".1f"), r["status"].replace("|", "/")]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main(out, timeout="900"):
    commands = {}
    for line in open(os.path.join(out, "commands.txt")):
        if line.strip():
            name, tool, command = line.rstrip("\n").split("|", 2)
            commands[(name, tool)] = command
    rows = [run(out, name, tool, command, timeout) for (name, tool), command in commands.items()]
    notes = skipped_notes(out)
    md = table(rows) + "".join(f"\n{n}" for n in notes) + ("\n" if notes else "")
    write_summary(out, md, {"runs": rows, "skipped": notes})


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(*sys.argv[1:3])
