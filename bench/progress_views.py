"""What the user sees of a job's progress, view by view (issue 53 acceptance 3; bench/progress_honesty.sh).

    progress_views.py stamp < OUTPUT > FILE.tsv
        each line (or in-place rewrite: text between carriage returns) of OUTPUT as "<Unix s>\\t<text>"
    progress_views.py analyse DIR NAME
        reads DIR/NAME.tsv (bench/progress_recorder: every LCM progress message and the end message),
        NAME.watch.tsv (`cyclopt watch` on a terminal, stamped), NAME.top.tsv (`cyclopt top
        --interval 1` to a pipe, stamped) and NAME.page.tsv (the dashboard's job page, its progress
        line each time it changed: bench/dashboard_bench.js follow) and prints per view: how many
        percentages it showed, whether one ever decreased, when 100 % first showed against the job's
        end message, and the ETA's error at 50 %: at the first percentage >= 50 the ETA shown
        against the real rest of the run (negative: too short).
"""

import re
import sys
import time

PERCENT = re.compile(r"(>=)?(\d+(?:\.\d+)?)%")
ETA = re.compile(r"ETA (\?|\d+ s|\d+:\d\d(?::\d\d)?)")


def stamp() -> None:
    out, pending = sys.stdout, b""
    while chunk := sys.stdin.buffer.read1(4096):
        pending += chunk
        *done, pending = re.split(rb"[\r\n]", pending)
        now = time.time()
        for segment in done:
            text = segment.decode(errors="replace").strip()
            if text:
                out.write(f"{now:.3f}\t{text}\n")
        out.flush()


def seconds(text: str) -> float | None:
    """'47 s', '2:57', '1:02:03' as seconds; '?' or '-' as None."""
    if text.endswith(" s"):
        return float(text[:-2])
    if re.fullmatch(r"\d+(:\d\d)+", text):
        value = 0.0
        for part in text.split(":"):
            value = 60 * value + int(part)
        return value
    return None


def recorder(path: str) -> tuple[list[tuple[float, float, float | None]], float, float, str]:
    """The messages (time, percent, ETA), the job's start and end times (Unix s) and its final state."""
    shown, start, end, state = [], None, None, "?"
    for line in open(path):
        f = line.rstrip("\n").split("\t")
        if f[0] == "end":
            end, state = float(f[1]), f[2]
            continue
        t, percent, eta, elapsed = float(f[0]), float(f[1]), float(f[3]), float(f[4])
        start = t - elapsed if start is None else start
        shown.append((t, percent, None if eta != eta else eta))
    return shown, start, end, state


def text_view(path: str, job: int | None = None) -> list[tuple[float, float, float | None]]:
    """(time, percent, ETA) of each stamped progress text: watch's line, the page's line."""
    shown = []
    for line in open(path):
        t, _, text = line.rstrip("\n").partition("\t")
        if t == "end":
            continue
        if job is not None and not text.startswith(f"job {job} "):
            continue
        p = PERCENT.search(text)
        if not p:
            continue
        eta = ETA.search(text)
        shown.append((float(t), float(p.group(2)), seconds(eta.group(1)) if eta else None))
    return shown


def top_view(path: str, job: int) -> list[tuple[float, float, float | None]]:
    """(time, percent, ETA) of the job's row in each table `cyclopt top` printed."""
    shown, cols = [], None
    for line in open(path):
        t, _, text = line.rstrip("\n").partition("\t")
        if text.startswith("ID "):
            cols = {name: text.index(name) for name in ("PROG", "BEST", "ETA", "RUN")}
            continue
        if cols is None or not text.split() or text.split()[0] != str(job):
            continue
        p = PERCENT.search(text[cols["PROG"]:cols["BEST"]])
        if p:
            shown.append((float(t), float(p.group(2)), seconds(text[cols["ETA"]:cols["RUN"]].strip())))
    return shown


def report(view: str, shown: list[tuple[float, float, float | None]], start: float, end: float) -> None:
    if not shown:
        print(f"  {view:9s} showed no percentage")
        return
    back = [a[1] - b[1] for a, b in zip(shown, shown[1:]) if b[1] < a[1]]
    hundred = next((t for t, p, _ in shown if p >= 100), None)
    half = next(((t, e) for t, p, e in shown if p >= 50), None)
    line = f"  {view:9s} {len(shown):4d} shown, decreased {len(back)} times"
    if back:
        line += f" (largest step back {max(back):.1f} points)"
    line += "; 100% " + (f"first {hundred - end:+.2f} s from the end message" if hundred is not None else "never shown")
    line += f"; last shown {shown[-1][1]:.0f}%"
    if half:
        t, eta = half
        rest = end - t
        if eta is None:
            line += f"; at 50% ({t - start:.1f} s): ETA not shown"
        else:
            line += (f"; at 50% ({t - start:.1f} s): ETA {eta:.0f} s, real rest {rest:.1f} s, "
                     f"error {eta - rest:+.1f} s ({100 * (eta - rest) / rest:+.0f}% of the rest)")
    print(line)


def analyse(directory: str, name: str, job: int) -> None:
    messages, start, end, state = recorder(f"{directory}/{name}.tsv")
    print(f"{name} (job {job}): run {end - start:.1f} s, ended {state}")
    report("messages", messages, start, end)
    report("watch", text_view(f"{directory}/{name}.watch.tsv", job), start, end)
    report("top", top_view(f"{directory}/{name}.top.tsv", job), start, end)
    report("dashboard", text_view(f"{directory}/{name}.page.tsv"), start, end)


if __name__ == "__main__":
    if sys.argv[1:2] == ["stamp"]:
        stamp()
    elif sys.argv[1:2] == ["analyse"] and len(sys.argv) == 5:
        analyse(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    else:
        sys.exit(__doc__)
