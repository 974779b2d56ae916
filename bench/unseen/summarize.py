#!/usr/bin/python3
"""Table of a run-defaults.sh output directory: OUTDIR/summary.md, OUTDIR/summary.json, stdout.

usage: /usr/bin/python3 summarize.py OUTDIR [TIMEOUT_SECONDS] [COMMAND_NOTE]
Per case (OUTDIR/cases.txt: name|cloud|reference|genus|parts) it reads NAME.rc, NAME.time
(/usr/bin/time -v), NAME.err, NAME.json (sltk --json) and counts the boundary and non-manifold
edges of NAME.ply with vtkFeatureEdges (sltk's JSON does not report them).
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from summary import skipped_notes, timing, write_summary  # noqa: E402

from vtkmodules.vtkFiltersCore import vtkFeatureEdges
from vtkmodules.vtkIOPLY import vtkPLYReader


def edges(ply):
    """(boundary edges, non-manifold edges) of a surface file."""
    reader = vtkPLYReader()
    reader.SetFileName(ply)
    counts = []
    for boundary in (True, False):
        fe = vtkFeatureEdges()
        fe.SetInputConnection(reader.GetOutputPort())
        fe.FeatureEdgesOff()
        fe.ManifoldEdgesOff()
        fe.SetBoundaryEdges(boundary)
        fe.SetNonManifoldEdges(not boundary)
        fe.Update()
        counts.append(fe.GetOutput().GetNumberOfLines())
    return counts




def case(out, line, timeout):
    name, cloud, ref, genus, parts = line.rstrip("\n").split("|")
    p = lambda ext: os.path.join(out, name + ext)
    rc = int(open(p(".rc")).read()) if os.path.exists(p(".rc")) else None
    wall, rss = timing(p(".time"))
    err = [l.strip() for l in open(p(".err"))] if os.path.exists(p(".err")) else []
    first_error = next((l for l in err if "error" in l.lower()), next((l for l in err if l), ""))
    status = ("ok" if rc == 0 else "not run" if rc is None
              else f"timeout {timeout} s" if rc == 124 else f"exit {rc}: {first_error}")
    r = {"name": name, "cloud": cloud, "reference": ref or None, "status": status, "exit": rc,
         "wall_s": wall, "peak_rss_mb": rss,
         "expected_genus": int(genus) if genus else None, "expected_parts": int(parts) if parts else None}
    j = json.load(open(p(".json"))) if os.path.exists(p(".json")) else {}
    r.update({k: j.get(k) for k in ("points", "points_reconstructed", "outliers_removed", "thinning_cell",
                                    "h_P", "cdx", "kp", "surface_pieces", "euler_characteristic",
                                    "chamfer", "hausdorff", "automatic_choices", "recoveries")})
    r["grids"] = ["x".join(map(str, run["grid"])) for run in j.get("runs", [])]
    r["boundary_edges"] = r["nonmanifold_edges"] = r["genus"] = None
    if os.path.exists(p(".ply")):
        r["boundary_edges"], r["nonmanifold_edges"] = edges(p(".ply"))
        if r["boundary_edges"] == 0 and r["euler_characteristic"] is not None:
            r["genus"] = (2 * r["surface_pieces"] - r["euler_characteristic"]) / 2
    return r


def fmt(v, spec=""):
    if v is None:
        return "-"
    if isinstance(v, float) and v.is_integer() and not spec:
        return str(int(v))
    return format(v, spec)


def table(rows):
    head = ("| cloud | status | wall s | RSS MB | points (used) | C_dx, K_P | grids (runs 1..n) | pieces | chi | genus "
            "| expected g/p | bnd edges | Chamfer | Hausdorff | verdict |")
    lines = [head, "|" + "---|" * head.count(" | ") + "---|"]
    for r in rows:
        verdict = ""
        if r["status"] == "ok":
            bad = []
            if r["expected_parts"] is not None and r["surface_pieces"] != r["expected_parts"]:
                bad.append("parts")
            if r["expected_genus"] is not None and r["genus"] != r["expected_genus"]:
                bad.append("genus")
            if r["boundary_edges"] or r["nonmanifold_edges"]:
                bad.append("not closed")
            verdict = "WRONG " + ", ".join(bad) if bad else "ok" if r["expected_genus"] is not None else "?"
        lines.append("| " + " | ".join([
            r["name"], r["status"].replace("|", "/"), fmt(r["wall_s"], ".1f"), fmt(r["peak_rss_mb"], ".0f"),
            fmt(r["points"]) + ("" if r["points_reconstructed"] in (None, r["points"])
                                else f" ({r['points_reconstructed']})"),
            f"{fmt(r['cdx'], '.3g')}, {fmt(r['kp'], '.3g')}", " / ".join(r["grids"]) or "-", fmt(r["surface_pieces"]),
            fmt(r["euler_characteristic"]), fmt(r["genus"]),
            f"{fmt(r['expected_genus'])}/{fmt(r['expected_parts'])}",
            fmt(r["boundary_edges"]) + ("" if not r["nonmanifold_edges"] else f" (+{r['nonmanifold_edges']} nm)"),
            fmt(r["chamfer"], ".3g"), fmt(r["hausdorff"], ".3g"), verdict]) + " |")
    return "\n".join(lines) + "\n"


def main(out, timeout="900", note=""):
    rows = [case(out, l, timeout) for l in open(os.path.join(out, "cases.txt")) if l.strip()]
    notes = skipped_notes(out)
    md = (f"`{note}`\n\n" if note else "") + table(rows) + "".join(f"\n{n}" for n in notes)
    write_summary(out, md, {"command": note, "cases": rows})


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(*sys.argv[1:4])
