"""The medians of bench/mpi/*-ranks.sh: each script alternates 1 and 2 ranks
REPEAT times and leaves in OUT, per rank count and repetition, the --json
summary (<ranks>.<r>.json, its "seconds"), the wall time of the mpirun
(wall.<ranks>.<r>) and one /usr/bin/time -v report per rank
(time.<ranks>.<r>.<rank>, from rank-rss.sh)."""
import glob
import json
import re
import statistics


def median(out, repeat, ranks, what):
    """The median over the repetitions of "seconds" (--json), "wall" or "rss"
    (the largest rank's peak RSS, MB)."""
    values = []
    for r in range(1, repeat + 1):
        if what == "wall":
            values.append(float(open(f"{out}/wall.{ranks}.{r}").read()))
        elif what == "rss":
            values.append(max(int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f).read()).group(1))
                              for f in glob.glob(f"{out}/time.{ranks}.{r}.*")) / 1024)
        else:
            values.append(json.load(open(f"{out}/{ranks}.{r}.json"))["seconds"])
    return statistics.median(values)


def print_medians(out, repeat, seconds_name):
    """One line each for the --json seconds (named `seconds_name`), the wall
    time and the peak RSS: 1 rank, 2 ranks and their ratio."""
    for what, name, unit in (("seconds", seconds_name, "s"), ("wall", "wall", "s"), ("rss", "rss", "MB")):
        one, two = median(out, repeat, 1, what), median(out, repeat, 2, what)
        ratio = f"speed-up {one / two:.2f}x" if what != "rss" else f"2-rank/1-rank {two / one:.2f}"
        print(f"median {name}: 1 rank {one:.2f} {unit}, 2 ranks {two:.2f} {unit}, {ratio}")
