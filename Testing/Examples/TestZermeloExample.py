"""Runs Examples/Python/paraview/zermelo_reachable_set.py small: it must write its PNG, and its
reachable sets (Test 5, (3.40)) must agree with a twice finer reference to a few percent at t = 3."""
import os
import shutil
import subprocess
import sys
import tempfile

pvpython, example, plugin = sys.argv[1:4]
png = os.path.join(tempfile.mkdtemp(prefix="sltk-zermelo-"), "zermelo.png")
p = subprocess.run([pvpython, "--force-offscreen-rendering", example, "--plugin", plugin, "--nodes", "51",
                    "--reference", "101", "--png", png], capture_output=True, text=True, timeout=600)
print(p.stdout, p.stderr)
assert p.returncode == 0, "the example failed"
assert os.path.getsize(png) > 20000, "no picture"
rows = [line.split() for line in p.stdout.splitlines() if line.strip().startswith("3.00")]
assert rows, "no t = 3 row"
t, area, reference, difference = map(float, rows[0])
assert 10.0 < reference < 20.0, reference  # the swimmer reaches a large part of the domain by t = 3
assert difference < 0.05, difference     # measured 0.015 at 51 vs 101 nodes
print("ok: |R xor R_ref| / |R_ref| = %.4f at t = 3" % difference)
shutil.rmtree(os.path.dirname(png), ignore_errors=True)
