"""The bad-input suite: one ctest test per case (BadInput.<name>, label badinput).

Every case gives SLTK something broken, through the CLI, the Python-wrapped
filters or the ParaView plugin in pvpython, and checks what a user gets back:
the exit code, the words of the message (the problem and the fix), and, for
every case, that nothing crashed (no signal, no abort), nothing hung (a time
limit), no input file changed, no output named by the case exists after a
failure, and no `.part` temporary is left.

  python3 BadInputCases.py --list        the case names (CMake reads them)
  python3 BadInputCases.py NAME          runs one case
Environment: SLTK_EXE (sltk), SLTK_PVPYTHON, SLTK_PLUGIN (SLTKPlugin.so),
SLTK_PYTHONPATH (the wrapped filters' site directory).
"""
import glob
import hashlib
import json
import math
import os
import signal
import shutil
import subprocess
import sys
import tempfile
import time

import BadFiles as bad

CASES = {}
TIME_LIMIT = 240  # seconds: beyond this a case counts as a hang


def case(name):
    def register(function):
        assert name not in CASES, name
        CASES[name] = function
        return function
    return register


class Sandbox:
    """A scratch folder, the inputs written there (checked unchanged) and the outputs named (checked absent)."""

    def __init__(self):
        self.dir = tempfile.mkdtemp(prefix="sltk-badinput-")
        self.inputs = {}
        self.outputs = []
        self.rc, self.out, self.err = None, "", ""
        self.problems = []
        self.signalled = ()  # signals the case sent itself: dying of them is the expected end

    def file(self, name, data):
        path = os.path.join(self.dir, name)
        with open(path, "wb") as f:
            f.write(data if isinstance(data, bytes) else data.encode())
        self.inputs[path] = hashlib.sha256(open(path, "rb").read()).hexdigest()
        return path

    def output(self, name):
        path = os.path.join(self.dir, name)
        self.outputs.append(path)
        return path

    def run(self, command, env=None, stdin_code=None):
        try:
            p = subprocess.run(command, capture_output=True, text=True, timeout=TIME_LIMIT, env=env,
                               input=stdin_code, cwd=self.dir, errors="replace")
        except subprocess.TimeoutExpired:
            self.problems.append("no answer within %d s: a hang" % TIME_LIMIT)
            self.rc = None
            return
        self.rc, self.out, self.err = p.returncode, p.stdout, p.stderr

    def sltk(self, *args):
        self.run([os.environ["SLTK_EXE"], *args])

    def python(self, code):
        """Runs `code` in /usr/bin/python3 with the wrapped filters (module sltk) and an error catcher."""
        env = dict(os.environ, PYTHONPATH=os.environ.get("SLTK_PYTHONPATH", ""))
        self.run(["/usr/bin/python3", "-c", PYTHON_PRELUDE + code], env=env)

    def pvpython(self, code):
        """Runs `code` in pvpython with the SLTK plugin loaded (paraview.simple)."""
        script = self.file("case_script.py", PVPYTHON_PRELUDE + code)
        self.run([os.environ["SLTK_PVPYTHON"], "--force-offscreen-rendering", script, os.environ["SLTK_PLUGIN"]])

    def fails(self, rc, *words):
        """The command ended with exit code `rc` and its messages contain every one of `words`."""
        if self.rc != rc:
            self.problems.append("exit code %s, expected %s" % (self.rc, rc))
        text = self.err + self.out
        for w in words:
            if w not in text:
                self.problems.append("the message does not say %r" % w)
        for path in self.outputs:
            if os.path.exists(path):
                self.problems.append("output %s was written by a failed command" % os.path.basename(path))

    def finish(self, name):
        if self.rc is not None and -self.rc not in self.signalled and (self.rc < 0 or self.rc in (134, 136, 139)):
            self.problems.append("the process died (exit %s): a crash" % self.rc)
        for path, digest in self.inputs.items():
            if not os.path.exists(path) or hashlib.sha256(open(path, "rb").read()).hexdigest() != digest:
                self.problems.append("input %s was changed or removed" % os.path.basename(path))
        left = [os.path.basename(p) for p in glob.glob(os.path.join(self.dir, "*.part*"))]
        if left:
            self.problems.append("temporaries left behind: %s" % left)
        print("%s: exit %s\n--- stderr (last 1500 characters)\n%s" % (name, self.rc, self.err[-1500:]))
        for p in self.problems:
            print("FAIL " + p)
        return not self.problems


PYTHON_PRELUDE = """
import sys
from vtkmodules.vtkCommonCore import vtkCommand, vtkLogger, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
import sltk
vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
errors = []

@calldata_type(VTK_STRING)
def on_error(caller, event, message):
    errors.append(message)
    print("ERROR: " + message, file=sys.stderr)

def watched(f):
    f.AddObserver(vtkCommand.ErrorEvent, on_error)
    return f

def cloud(points):
    p = vtkPoints()
    for x in points:
        p.InsertNextPoint(*x)
    c = vtkPolyData()
    c.SetPoints(p)
    return c

def sphere(n=300):
    import math
    return cloud([(math.sqrt(1 - (-1 + 2 * (k + 0.5) / n) ** 2) * math.cos(2.4 * k),
                   math.sqrt(1 - (-1 + 2 * (k + 0.5) / n) ** 2) * math.sin(2.4 * k), -1 + 2 * (k + 0.5) / n)
                  for k in range(n)])

def refused(f, what):
    f.Update()
    out = f.GetOutputDataObject(0)
    assert errors, what + ": no error"
    empty = out.GetNumberOfPoints() == 0 if hasattr(out, "GetNumberOfPoints") else out.GetNumberOfCells() == 0
    assert empty, what + ": an output was produced"  # an image, or OctreeStorage's hyper tree grid
    sys.exit(3)  # the expected end of a refused case: the runner checks this code and the message
"""

PVPYTHON_PRELUDE = """
import sys
from paraview.simple import *
LoadPlugin(sys.argv[1], ns=globals())

def refused(proxy, what):
    proxy.UpdatePipeline()
    assert proxy.GetDataInformation().GetNumberOfPoints() == 0, what + ": an output was produced"
    sys.exit(3)
"""


# ---------------------------------------------------------------- the cloud file
def cloud_case(name, data, extension, rc, *words, args=()):
    @case("cli.cloud." + name)
    def _(t):
        cloud = t.file("cloud" + extension, data)
        t.sltk("reconstruct", cloud, "-o", t.output("out.vti"), "--quiet", *args)
        t.fails(rc, *words)


cloud_case("empty-file", b"", ".xyz", 1, "empty")
cloud_case("header-only", b"x y z\n", ".xyz", 1, "empty")
cloud_case("empty-vtk", b"", ".vtk", 1, "is empty (0 bytes)", "no points")
cloud_case("ply-faces-without-vertices", b"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
           b"end_header\n3 0 1 2\n", ".ply", 1, "has no vertices", "no points to reconstruct")
cloud_case("binary-garbage", bad.garbage(), ".xyz", 1, "binary data")
cloud_case("token-with-letters", b"0 0 0\n1 0 0\n0 1 0.02abc\n0 0 1\n", ".xyz", 1, "'0.02abc' is not a number", ":3:")
cloud_case("nan-coordinate", bad.with_line(200, 17, "nan 0 0\n"), ".xyz", 1, "point 17", "non-finite")
cloud_case("inf-coordinate", bad.with_line(200, 5, "0 inf 0\n"), ".xyz", 1, "point 5", "non-finite")
cloud_case("two-points", b"0 0 0\n1 1 1\n", ".xyz", 1, "needs at least 4")
cloud_case("coincident-points", b"1 2 3\n" * 50, ".xyz", 1, "coincide")
cloud_case("collinear-3d", bad.rows([(t / 50, 2 * t / 50, 3 * t / 50) for t in range(50)]), ".xyz", 1,
           "all points lie on one line")
cloud_case("collinear-2d", bad.rows([(t / 50, 2 * t / 50, 0) for t in range(50)]), ".xyz", 1,
           "all points lie on one line", "closed curve")
cloud_case("exactly-planar-tilted", bad.rows([(i, j, -i - j) for i in range(8) for j in range(8)], "%d %d %d\n"), ".xyz",
           1, "all points lie on one plane", "2D reconstruction")
cloud_case("tilted-disc", bad.tilted_disc(), ".xyz", 1, "the cloud is flat", "normal (", "no K_P or eta can help")
cloud_case("coordinates-near-1e308", bad.rows([tuple(c * 1e307 for c in p) for p in bad.sphere_points(200)], "%.17g %.17g %.17g\n"),
           ".xyz", 1, "coordinates reach", "rescale the cloud")
cloud_case("tiny-extent-far-away", bad.rows([tuple(1e9 + 1e-3 * c for c in p) for p in bad.sphere_points(200)],
                                            "%.17g %.17g %.17g\n"), ".xyz", 1, "translate the points")
cloud_case("lone-outlier-without-cleaning", bad.sphere(400) + b"1000 1000 1000\n", ".xyz", 1, "stray point",
           "--remove-outliers", args=("--no-cleaning",))
cloud_case("unknown-extension", bad.sphere(50), ".foo", 1, ".foo")
for _name, (_data, _words) in bad.DAMAGED_PLY.items():
    cloud_case("ply-" + _name, _data, ".ply", 1, "damaged PLY file", _words)


@case("cli.cloud.missing-file")
def _(t):
    t.sltk("reconstruct", os.path.join(t.dir, "nowhere.xyz"), "-o", t.output("out.vti"))
    t.fails(1, "cannot open")


@case("cli.cloud.folder")
def _(t):
    os.mkdir(os.path.join(t.dir, "scans.xyz"))
    t.sltk("info", os.path.join(t.dir, "scans.xyz"))
    t.fails(1, "is a folder")


def reference_case(name, data, words):
    @case("cli.reference.ply-" + name)
    def _(t):
        cloud = t.file("cloud.xyz", bad.sphere(200))
        reference = t.file("reference.ply", data)
        t.sltk("reconstruct", cloud, "--reference", reference, "-o", t.output("out.vti"))
        t.fails(1, "damaged PLY file", words)


for _name, (_data, _words) in bad.DAMAGED_PLY.items():
    reference_case(_name, _data, _words)


@case("cli.reference.point-file")
def _(t):
    cloud = t.file("cloud.xyz", bad.sphere(200))
    t.sltk("reconstruct", cloud, "--reference", cloud, "-o", t.output("out.vti"))
    t.fails(1, "unsupported reference mesh")


# ---------------------------------------------------------------- outputs
for _option in ("-o", "--json", "--csv", "--surface"):
    def _output_names_input(t, option=_option):
        cloud = t.file("cloud.ply", bad.ply_header("ascii", 200) + bad.sphere(200))
        t.sltk("reconstruct", cloud, option, cloud)
        t.fails(2, "would be overwritten")
    case("cli.output.%s-names-the-cloud" % _option.strip("-"))(_output_names_input)


@case("cli.output.two-outputs-one-file")
def _(t):
    cloud = t.file("cloud.xyz", bad.sphere(200))
    same = t.output("out.json")
    t.sltk("reconstruct", cloud, "--json", same, "--csv", same)
    t.fails(2)


def output_case(name, option, filename, *words):
    """`sltk reconstruct CLOUD OPTION FILENAME` is a usage error (exit 2) before any work."""
    @case("cli.output." + name)
    def _(t):
        t.sltk("reconstruct", t.file("cloud.xyz", bad.sphere(200)), option, t.output(filename))
        t.fails(2, *words)


output_case("missing-folder", "-o", "no-such-folder/out.vti", "does not exist")
output_case("extension-not-written", "-o", "sdf.xyz", ".vti")
output_case("surface-format", "--surface", "s.obj", ".vtp, .ply or .stl")


@case("cli.output.is-a-folder")
def _(t):
    t.sltk("hjb", "--preset", "test1", "--n", "21", "-o", t.dir)
    t.fails(2, "is a folder")


@case("cli.output.curve-as-ply")
def _(t):
    import math
    flower = t.file("flower.xyz", bad.rows([((1 + 0.3 * math.cos(3 * a)) * math.cos(a), math.sin(a), 0)
                                            for a in [2 * math.pi * k / 200 for k in range(200)]]))
    t.sltk("reconstruct", flower, "--surface", t.output("flower.ply"))
    t.fails(2, ".vtp")


@case("cli.output.hjb-json-extension")
def _(t):
    t.sltk("hjb", "--preset", "test1", "--n", "21", "--json", t.output("summary.txt"))
    t.fails(2, ".json")


@case("cli.output.info-json-names-the-cloud")
def _(t):
    cloud = t.file("cloud.xyz", bad.sphere(200))
    t.sltk("info", cloud, "--json", cloud)
    t.fails(2, "would be overwritten")


@case("cli.output.interrupted-write")
def _(t):
    """SIGINT while the output is written: the temporary is removed, nothing half-written stays."""
    out = t.output("value.vti")
    p = subprocess.Popen([os.environ["SLTK_EXE"], "hjb", "--preset", "test1", "--n", "2001", "--final-time", "0.001",
                          "-o", out], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seen = False
    for _ in range(6000):
        if glob.glob(os.path.join(t.dir, "value.part*")):
            p.send_signal(signal.SIGINT)
            t.signalled = (signal.SIGINT,)
            seen = True
            break
        if p.poll() is not None:
            break
        time.sleep(0.005)
    _, t.err = p.communicate(timeout=120)
    t.rc = p.returncode
    if not seen:
        t.problems.append("the write was not caught (no .part file seen): the case did not test anything")
    t.fails(t.rc)


@case("cli.memory.address-space-limit")
def _(t):
    """An allocation the memory checks cannot foresee (an address-space limit they do not see): an error, not an abort."""
    import resource
    cloud = t.file("cloud.xyz", bad.sphere(2562))
    out = t.output("limited.vti")
    p = subprocess.run([os.environ["SLTK_EXE"], "reconstruct", cloud, "--cdx", "0.5", "-o", out], capture_output=True,
                       text=True, timeout=TIME_LIMIT,
                       preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS, (400 << 20, 400 << 20)))
    t.rc, t.out, t.err = p.returncode, p.stdout, p.stderr
    t.fails(1, "out of memory")


@case("cli.output.interrupted-run")
def _(t):
    """SIGINT during a long solve: exit at once, no output, no temporary."""
    out = t.output("value.vti")
    p = subprocess.Popen([os.environ["SLTK_EXE"], "hjb", "--preset", "test4", "--n", "1501", "-o", out],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    t.signalled = (signal.SIGINT,)
    try:
        _, t.err = p.communicate(timeout=60)
        t.rc = p.returncode
    except subprocess.TimeoutExpired:
        p.kill()
        t.problems.append("SIGINT did not stop the run within 60 s")
        return
    if t.rc == 0:
        t.problems.append("an interrupted run exited 0")
    t.fails(t.rc)


# ---------------------------------------------------------------- options
def option_case(name, args, rc, *words, command="reconstruct"):
    @case("cli.option." + name)
    def _(t):
        if command == "reconstruct":
            t.sltk("reconstruct", t.file("cloud.xyz", bad.sphere(200)), "-o", t.output("out.vti"), *args)
        else:
            t.sltk(command, *args)
        t.fails(rc, *words)


option_case("cdx-negative", ("--cdx", "-1"), 2, "--cdx")
option_case("cdx-not-a-number", ("--cdx", "zero"), 2, "expects a number")
option_case("cdx-trailing-text", ("--cdx", "1x"), 2, "--cdx", "expects a number")
option_case("runs-100", ("--runs", "100"), 2, "--runs", "[1, 6]")
option_case("threads-10000", ("--threads", "10000"), 2, "--threads", "1024")
option_case("schedule-odd", ("--schedule", "1:0,2"), 2, "p:eta pairs")
option_case("schedule-out-of-range", ("--schedule", "1:0,2:200"), 2, "pair 2")
option_case("eta-with-schedule", ("--schedule", "1:0,2:0,2:1", "--eta", "2"), 2, "either --eta or --schedule")
option_case("unknown-interpolator", ("--interpolator", "rbf"), 2, "q1, weno3, cweno, cwenoz or lsq-q1")
# The thesis's chapter 5 least squares is the reconstruction's only.
option_case("hjb-lsq-interpolator", ("--preset", "test2", "--n", "41", "--interpolator", "lsq-q1"), 2,
            "q1, weno3, cweno or cwenoz", command="hjb")
option_case("thin-negative", ("--thin", "-1"), 2, "--thin")
option_case("sigma-without-removal", ("--outlier-sigma", "2"), 2, "--remove-outliers")
option_case("thin-to-nothing", ("--thin", "100"), 1, "after cleaning")
option_case("grid-beyond-memory", ("--cdx", "0.05", "--memory-budget", "16"), 1, "use C_dx >=")
option_case("cdx-missing-value", ("--cdx",), 2, "--cdx", "needs a value")
option_case("max-level-with-cdx", ("--max-level", "8", "--cdx", "1"), 2, "excludes")
option_case("max-level-31", ("--max-level", "31"), 2, "--max-level", "[1, 30]")
option_case("max-level-beyond-memory", ("--max-level", "9", "--memory-budget", "16"), 1,
            "use MaximumLevel (--max-level) <=", "the finest level that fits")


@case("cli.option.large-cloud-beyond-memory")
def _(t):
    """A large cloud refused for memory gets the merged-scan hint (thinning) besides the C_dx."""
    t.sltk("info", t.file("big.xyz", bad.sphere(120000)), "--cdx", "0.05", "--memory-budget", "16")
    t.fails(1, "use C_dx >=", "--thin 2.5")


@case("cli.option.objects-far-apart-beyond-memory")
def _(t):
    """Two small objects far apart in one file: the refusal names the sizes and their own runs, not only a C_dx."""
    two = bad.sphere_points(2000) + [(p[0] + 300, p[1] + 300, p[2] + 300) for p in bad.sphere_points(2000)]
    t.sltk("info", t.file("two.xyz", bad.rows(two)), "--cdx", "1", "--memory-budget", "64")
    t.fails(1, "GB", "use C_dx >=", "2 groups of points", "reconstruct each group in its own run")
@case("cli.cloud.objects-far-apart-coarse-grid")
def _(t):
    """Two objects far apart under a small budget: the automatic C_dx is coarse for each; the refusal
    (the grid is flat at its cells) names their own runs, not a C_dx. Along one axis the grid fits:
    the first attempt breaks the spheres into pieces, and the restarts on the pieces (half the
    C_dx, then one run on the finest grid that fits: 1.02, up the automatic C_dx's ladder from the
    half, 0.74, whose run 1 with its padding passes the budget) give the two spheres (they were 9 pieces and
    a statement that the result does not fit before the restarts followed the pieces)."""
    along = bad.sphere_points(1500) + [(p[0] + 300, p[1], p[2]) for p in bad.sphere_points(1500)]
    t.sltk("reconstruct", t.file("along.xyz", bad.rows(along)), "--memory-budget", "128", "--json", "along.json")
    t.fails(0, "pieces where the cloud has 2 connected component(s)", "with 1 run(s)", "2 piece(s)",
            "the finest grid that fits the memory budget (run 1's padding")
    summary = json.load(open(os.path.join(t.dir, "along.json")))
    if summary.get("surface_pieces") != 2 or summary.get("fits_cloud") is not True:
        t.problems.append("--json: surface_pieces %r, fits_cloud %r" % (summary.get("surface_pieces"),
                                                                       summary.get("fits_cloud")))
    diagonal = bad.sphere_points(1500) + [(p[0] + 300, p[1] + 300, p[2] + 300) for p in bad.sphere_points(1500)]
    t.sltk("reconstruct", t.file("diagonal.xyz", bad.rows(diagonal)), "--memory-budget", "64")
    t.fails(1, "too coarse for the objects", "2 groups of points", "reconstruct each group in its own run")
    if "is flat" in t.err:
        t.problems.append("two spheres called a flat cloud")


option_case("unknown-option", ("--frobnicate",), 2, "--frobnicate")


@case("cli.option.octree-with-image-pieces")
def _(t):
    """--octree's ranks hold trees: -o FILE.pvti is refused before any work, naming .phtg and .vti."""
    t.sltk("reconstruct", t.file("cloud.xyz", bad.sphere(200)), "--octree", "-o", t.output("out.pvti"))
    t.fails(2, "--octree's ranks hold trees", ".phtg", ".vti on one rank")


@case("cli.option.tree-output-without-octree")
def _(t):
    """-o FILE.htg is --octree's output: refused without it, before any work, no file written."""
    t.sltk("reconstruct", t.file("cloud.xyz", bad.sphere(200)), "-o", t.output("out.htg"))
    t.fails(2, "-o FILE.htg is --octree's output", "add --octree")


option_case("unknown-command", ("frobnicate",), 2, "frobnicate", command="frobnicate")

# ---------------------------------------------------------------- HJB problems
CUSTOM_2D = ("hjb", "--fx", "a1", "--fy", "a2", "--controls", "box", "--control-dim", "2", "--nodes", "21,21",
             "--final-time", "0.1")


def hjb_case(name, args, rc, *words):
    @case("cli.hjb." + name)
    def _(t):
        t.sltk(*args, "-o", t.output("value.vti"), "--json", t.output("summary.json"))
        t.fails(rc, *words)


hjb_case("final-time-1e7", ("hjb", "--preset", "test1", "--n", "41", "--final-time", "1e7"), 1, "more than 1e+06",
         "final time")
hjb_case("tabulation-1e9-controls", ("hjb", "--fx", "a1", "--fy", "a2", "--fz", "a3", "--controls", "box",
                                     "--control-dim", "3", "--tabulation", "1000", "--nodes", "21,21,21",
                                     "--v0", "x*x+y*y+z*z"), 1, "control tabulation", "1e+09 controls",
         "at most 100 points per parameter")
hjb_case("courant-1e-9", CUSTOM_2D + ("--v0", "x", "--courant", "1e-9"), 1, "Courant", "1e+09 steps")
hjb_case("fz-in-2d", CUSTOM_2D + ("--v0", "x", "--fz", "1"), 2, "--fz is given for a 2D problem")
hjb_case("third-domain-pair", CUSTOM_2D + ("--v0", "x", "--domain", "-1,1,-1,1,-1,1"), 2,
         "--domain gives 3 axes for a 2D problem")
hjb_case("argmin-beyond-controls", CUSTOM_2D + ("--v0", "x", "--argmin3", "1"), 2, "--argmin3 is given for 2 control(s)")
hjb_case("exact-0-over-0", CUSTOM_2D + ("--v0", "x", "--exact", "0/0"), 1, "--exact", "x = -1, y = -1")
hjb_case("v0-one-over-x", CUSTOM_2D + ("--v0", "1/x"), 1, "the initial datum v0 '1/x' is +Inf at x = 0",
         "finite on the whole domain")
hjb_case("v0-log", CUSTOM_2D + ("--v0", "log(x)"), 1, "the initial datum v0 'log(x)' is NaN at x = -1")
hjb_case("dynamics-one-over-x", ("hjb", "--fx", "1/x", "--fy", "0", "--nodes", "21,21", "--v0", "x",
                                 "--final-time", "0.1"), 1, "the dynamics f_D component x '1/x' is +Inf at x = 0")
hjb_case("cost-sqrt-negative", CUSTOM_2D + ("--v0", "x", "--cost", "sqrt(-1-x^2)"), 1,
         "the running cost f_C 'sqrt(-1-x^2)' is NaN at x = -1")
hjb_case("domain-1e300", CUSTOM_2D + ("--v0", "x^2", "--domain", "-1e300,1e300,-1,1"), 1,
         "the initial datum v0 'x^2' is +Inf at x = -1e+300")
hjb_case("formula-syntax", CUSTOM_2D + ("--v0", "x", "--cost", "(a1^2 + a2^2/2"), 1, "running cost f_C", "column")
hjb_case("formula-unknown-variable", CUSTOM_2D + ("--v0", "q + x",), 1, "unknown variable 'q'")
hjb_case("unknown-preset", ("hjb", "--preset", "test9"), 2, "test1, test2")
hjb_case("too-few-nodes", ("hjb", "--n", "3"), 2, "--n")
hjb_case("unknown-control-set", ("hjb", "--fx", "y", "--v0", "x", "--nodes", "21,21", "--controls", "cone"), 2,
         "none, box, ball or sphere")
hjb_case("custom-option-on-preset", ("hjb", "--preset", "test1", "--cost", "1"), 2, "--fx")
hjb_case("malformed-number-list", ("hjb", "--fx", "y", "--v0", "x", "--nodes", "21,abc"), 2, "--nodes")
hjb_case("domain-reversed", CUSTOM_2D + ("--v0", "x", "--domain", "1,-1,-1,1"), 1, "lower < upper")


# ---------------------------------------------------------------- Python-wrapped filters
def script_case(prefix, interpreter):
    """Cases that run a script snippet in `interpreter` (a Sandbox method); the snippet ends with exit 3
    when the filter refused the input (the preludes' refused())."""
    def make(name, code, *words):
        @case(prefix + name)
        def _(t):
            getattr(t, interpreter)(code)
            t.fails(3, *words)
    return make


python_case = script_case("python.", "python")


python_case("recon-cell-size-negative", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(sphere()); f.SetCellSizeFactor(-1)
assert f.GetCellSizeFactor() == -1, "kept as given"
refused(f, "CellSizeFactor -1")""", "CellSizeFactor")
python_case("recon-cell-size-tiny", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(sphere()); f.SetCellSizeFactor(1e-6)
refused(f, "CellSizeFactor 1e-6")""", "CellSizeFactor")
python_case("recon-runs-100", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(sphere()); f.SetNumberOfRuns(100)
refused(f, "NumberOfRuns 100")""", "NumberOfRuns")
python_case("recon-odd-run-parameters", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(sphere())
f.AddRunParameterValue(1); f.AddRunParameterValue(0); f.AddRunParameterValue(2)
refused(f, "three RunParameters values")""", "RunParameters has 3 values", "pairs")
python_case("recon-empty-input", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(cloud([]))
refused(f, "an empty cloud")""", "empty")
python_case("recon-nan-point", """
f = watched(sltk.vtkSLLevelSetReconstruct()); c = sphere(); c.GetPoints().SetPoint(7, float("nan"), 0, 0)
f.SetInputData(c)
refused(f, "a NaN point")""", "point 7", "non-finite")
python_case("recon-tilted-disc", """
import math
u = (1 / math.sqrt(2), -1 / math.sqrt(2), 0.0); v = (1 / math.sqrt(6), 1 / math.sqrt(6), -2 / math.sqrt(6))
pts = [tuple(round(a * u[c] + b * v[c], 6) for c in range(3)) for a in [i / 10 - 1 for i in range(21)]
       for b in [j / 10 - 1 for j in range(21)] if a * a + b * b <= 1]
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(cloud(pts))
refused(f, "a flat cloud")""", "the cloud is flat")
python_case("recon-threads-100000", """
f = watched(sltk.vtkSLLevelSetReconstruct()); f.SetInputData(sphere()); f.SetNumberOfThreads(100000)
refused(f, "NumberOfThreads 100000")""", "NumberOfThreads")
python_case("hjb-nodes-3", """
f = watched(sltk.vtkCWENOHJBSolver()); f.SetNumberOfNodes(3)
refused(f, "NumberOfNodes 3")""", "NumberOfNodes")
python_case("hjb-final-time-1e9", """
f = watched(sltk.vtkCWENOHJBSolver()); f.SetNumberOfNodes(31); f.SetFinalTime(1e9)
refused(f, "FinalTime 1e9")""", "more than 1e+06")
python_case("hjb-formula-not-finite", """
f = watched(sltk.vtkCWENOHJBSolver()); f.SetPreset(sltk.vtkCWENOHJBSolver.CUSTOM)
f.SetDimensions(21, 21, 1); f.SetDomainBounds(-1, 1, -1, 1, 0, 0)
f.SetDynamicsX("-y"); f.SetDynamicsY("x"); f.SetInitialValue("log(x)"); f.SetFinalTime(0.1)
refused(f, "v0 = log(x)")""", "the initial datum v0 'log(x)' is NaN")
python_case("hjb-formula-syntax", """
f = watched(sltk.vtkCWENOHJBSolver()); f.SetPreset(sltk.vtkCWENOHJBSolver.CUSTOM)
f.SetDimensions(21, 21, 1); f.SetDynamicsX("-y +"); f.SetDynamicsY("x"); f.SetInitialValue("x")
refused(f, "a malformed formula")""", "the dynamics f_D component x", "column")
python_case("hjb-courant-negative", """
f = watched(sltk.vtkCWENOHJBSolver()); f.SetNumberOfNodes(31); f.SetCourantNumber(-1)
refused(f, "CourantNumber -1")""", "CourantNumber")
python_case("octree-storage-off", """
f = watched(sltk.vtkOctreeSDF()); f.SetInputDataObject(0, sphere()); f.OctreeStorageOff()
f.Update()
assert errors, "vtkOctreeSDF without its octree"
sys.exit(3)""", "use vtkSLLevelSetReconstruct")


# ---------------------------------------------------------------- the ParaView plugin (pvpython)
plugin_case = script_case("plugin.", "pvpython")


plugin_case("cell-size-zero-point-000001", """
r = SemiLagrangianLevelSetReconstruction(Input=Sphere(ThetaResolution=16, PhiResolution=16), CellSizeFactor=1e-6)
refused(r, "CellSizeFactor 1e-6")""", "CellSizeFactor")
plugin_case("runs-100", """
r = SemiLagrangianLevelSetReconstruction(Input=Sphere(ThetaResolution=16, PhiResolution=16), NumberOfRuns=100)
refused(r, "NumberOfRuns 100")""", "NumberOfRuns")
plugin_case("odd-run-parameters", """
r = SemiLagrangianLevelSetReconstruction(Input=Sphere(ThetaResolution=16, PhiResolution=16))
r.RunParameters = [1, 0, 2]
refused(r, "three RunParameters values")""", "RunParameters has 3 values")
plugin_case("hjb-formula-not-finite", """
h = CWENOHamiltonJacobiBellmanSolver(Preset="Custom (formulas below)", Dimensions=[21, 21, 1],
                                     DomainBounds=[-1, 1, -1, 1, 0, 0], DynamicsX="1/x", DynamicsY="0",
                                     InitialValue="x", FinalTime=0.1)
refused(h, "f_D = 1/x")""", "the dynamics f_D component x '1/x' is +Inf at x = 0")
plugin_case("hjb-nodes-3", """
h = CWENOHamiltonJacobiBellmanSolver(NumberOfNodes=3)
refused(h, "NumberOfNodes 3")""", "NumberOfNodes")


def main():
    if sys.argv[1:] == ["--list"]:
        print(";".join(CASES))
        return 0
    name = sys.argv[1]
    t = Sandbox()
    CASES[name](t)
    passed = t.finish(name)
    if passed:
        shutil.rmtree(t.dir, ignore_errors=True)  # a failed case keeps its folder to look at
    else:
        print("the case's files: " + t.dir)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
