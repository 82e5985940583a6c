#!/usr/bin/env python3
"""Conformance report: run every corpus scenario with oscsim and compare with esmini.

Usage (from the repository root):

    python3 scripts/conformance.py            # writes docs/conformance.md

Builds `oscsim` in release mode, runs every scenario of ../shared/corpus/esmini/xosc/ and
../shared/corpus/generated/xosc/ with `--dt 0.05` (trajectory CSV and event log under
target/conformance/), compares each run that has an esmini reference
(../shared/corpus/reference/esmini/NAME.csv and NAME.events.txt) with
../shared/tools/compare_run.py (default tolerances: 0.10 m, 0.10 m/s, 0.05 s), and writes
docs/conformance.md: one line per scenario with the outcome, the worst position and speed
errors over its entities, the events whose start time disagrees, and a hand-written reason
read from docs/conformance-notes.tsv (scenario <TAB> reason; kept across regenerations, edited
by hand), and the table of readings of docs/conformance-readings.tsv (motion, the standard's
text, esmini, oscsim, test) and of docs/conformance-asam-examples.tsv (ASAM's examples and their
equivalents). Options: --no-build (use the existing binary), --timeout SECONDS (per run, default
120), --only NAME (substring filter, for quick checks: prints the rows and leaves
docs/conformance.md alone unless --report is given), --bin PATH (the oscsim binary to run, e.g.
target/debug/oscsim with --no-build), --out DIR (where runs are written, default
target/conformance), --report PATH (where the report is written).
Standard library only.
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "..", "shared", "corpus")
COMPARE = os.path.join(ROOT, "..", "shared", "tools", "compare_run.py")
OUT = os.path.join(ROOT, "target", "conformance")
BIN = os.path.join(ROOT, "target", "release", "oscsim")
NOTES = os.path.join(ROOT, "docs", "conformance-notes.tsv")
READINGS = os.path.join(ROOT, "docs", "conformance-readings.tsv")
EXAMPLES = os.path.join(ROOT, "docs", "conformance-asam-examples.tsv")
REPORT = os.path.join(ROOT, "docs", "conformance.md")
SOURCES = [("esmini", "esmini/xosc"), ("generated", "generated/xosc")]


def read_notes():
    notes = {}
    if os.path.exists(NOTES):
        for line in open(NOTES, encoding="utf-8"):
            if line.startswith("#") or not line.strip():
                continue
            name, _, reason = line.rstrip("\n").partition("\t")
            notes[name.strip()] = reason.strip()
    return notes


def read_readings(path=READINGS):
    rows = []
    if os.path.exists(path):
        for line in open(path, encoding="utf-8"):
            if line.startswith("#") or not line.strip():
                continue
            rows.append([c.strip() for c in line.rstrip("\n").split("\t")])
    return rows


def last_error_line(text):
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    for l in lines:
        if l.lower().startswith("error"):
            return l
    return lines[-1] if lines else ""


def compare(name, csv, events):
    ref_csv = os.path.join(CORPUS, "reference", "esmini", name + ".csv")
    ref_events = os.path.join(CORPUS, "reference", "esmini", name + ".events.txt")
    if not os.path.exists(ref_csv):
        return None
    cmd = [sys.executable, COMPARE, "--ref-csv", ref_csv, "--csv", csv]
    if os.path.exists(ref_events) and os.path.exists(events):
        cmd += ["--ref-events", ref_events, "--events", events]
    p = subprocess.run(cmd, capture_output=True, text=True)
    worst_pos = worst_speed = 0.0
    bad_events, bad_entities = [], []
    summary = ""
    for line in p.stdout.splitlines():
        m = re.match(r"entity (\S+): (\S+)\s.*max_pos=([0-9.]+).*max_speed=([0-9.]+)", line)
        if m:
            worst_pos = max(worst_pos, float(m.group(3)))
            worst_speed = max(worst_speed, float(m.group(4)))
            if m.group(2) != "ok":
                bad_entities.append(m.group(1))
            continue
        m = re.match(r"entity (\S+): FAIL no common samples", line)
        if m:
            bad_entities.append(m.group(1) + " (no samples)")
            continue
        m = re.match(r"event (.+?): FAIL (.*)", line)
        if m:
            bad_events.append(f"{m.group(1)}: {m.group(2)}")
            continue
        if re.match(r"\d+ passed, \d+ failed", line):
            summary = line
    if not summary:
        summary = "compare_run.py failed: " + last_error_line(p.stderr)
    return {
        "ok": p.returncode == 0,
        "pos": worst_pos,
        "speed": worst_speed,
        "events": bad_events,
        "entities": bad_entities,
        "summary": summary,
    }


def run(path, name, timeout):
    csv = os.path.join(OUT, name + ".csv")
    events = os.path.join(OUT, name + ".jsonl")
    for f in (csv, events):
        if os.path.exists(f):
            os.remove(f)
    cmd = [BIN, "run", path, "--dt", "0.05", "--csv", csv, "--events", events, "--quiet"]
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        status = "ok" if p.returncode == 0 else f"exit {p.returncode}"
        err = "" if p.returncode == 0 else last_error_line(p.stderr)
    except subprocess.TimeoutExpired:
        status, err = "timeout", f"no result within {timeout} s"
    return status, err, time.monotonic() - start, csv, events


def log_summary(events):
    """(events started, {unsupported/error message: count}) from an oscsim event log."""
    started, unsupported = 0, {}
    if not os.path.exists(events):
        return started, unsupported
    for line in open(events, encoding="utf-8"):
        line = line.strip()
        if not line:
            continue
        e = json.loads(line)
        if e.get("kind") == "event" and e.get("transition") == "start":
            started += 1
        elif e.get("kind") in ("unsupported", "error"):
            m = e["kind"] + ": " + re.sub(r" at /.*", "", e.get("message", ""))
            unsupported[m] = unsupported.get(m, 0) + 1
    return started, unsupported


def controller_summary(path, events):
    """The user controllers of a scenario: {(entity, controller): (model, activated, notes)} from
    its event log's `controller` records, plus the ObjectControllers and
    AssignControllerActions written in the file that the log does not show (assigned and never
    activated: {(None, name): ("", False, [])})."""
    found = {}
    if os.path.exists(events):
        for line in open(events, encoding="utf-8"):
            line = line.strip()
            if not line:
                continue
            e = json.loads(line)
            if e.get("kind") != "controller":
                continue
            key = (e["entity"], e["controller"])
            model, active, notes = found.get(key, (e["model"], False, []))
            active = active or e["longitudinal"] or e["lateral"]
            note = re.sub(r"^(assigned|activation changed);? ?", "", e.get("note", ""))
            if note and note not in notes:
                notes.append(note)
            found[key] = (model, active, notes)
    text = open(path, encoding="utf-8", errors="replace").read()
    text = re.sub(r"<!--.*?-->", "", text, flags=re.S)
    written = re.findall(r"<Controller\s+name=\"([^\"]*)\"", text)
    written += re.findall(r"entryName=\"([^\"]*)\"[^>]*/>\s*</(?:ObjectController|AssignControllerAction)", text)
    shown = {c for (_, c) in found}
    for name in written:
        if name not in shown:
            found.setdefault((None, name), ("", False, []))
    return found


def cell(text):
    # Paths under the repository are shown relative to it, so the report does not depend on the
    # worktree it was made in.
    text = text.replace(ROOT + os.sep, "")
    return text.replace("|", "\\|").replace("\n", " ")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-build", action="store_true")
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--only", default="")
    ap.add_argument("--bin", default=None)
    ap.add_argument("--out", default=None)
    ap.add_argument("--report", default=None)
    a = ap.parse_args()
    global BIN, OUT
    BIN = os.path.abspath(a.bin) if a.bin else BIN
    OUT = os.path.abspath(a.out) if a.out else OUT
    report = a.report or (None if a.only else REPORT)
    if not a.no_build:
        subprocess.run(["cargo", "build", "--release", "-p", "oscsim-cli"], cwd=ROOT, check=True)
    os.makedirs(OUT, exist_ok=True)
    notes = read_notes()
    rows = []
    all_unsupported = {}
    controllers = []
    for source, folder in SOURCES:
        directory = os.path.join(CORPUS, folder)
        for file in sorted(os.listdir(directory)):
            if not file.endswith(".xosc") or a.only not in file:
                continue
            name = file[: -len(".xosc")]
            status, err, wall, csv, events = run(os.path.join(directory, file), name, a.timeout)
            result = compare(name, csv, events) if status == "ok" else None
            has_ref = os.path.exists(os.path.join(CORPUS, "reference", "esmini", name + ".csv"))
            if status != "ok":
                verdict = "error" if status.startswith("exit") else status
            elif result is None:
                verdict = "ran (no reference)" if not has_ref else "ran"
            else:
                verdict = "pass" if result["ok"] else "fail"
            found = controller_summary(os.path.join(directory, file), events)
            if found:
                controllers.append((source, name, found))
            started, unsupported = log_summary(events)
            for m, n in unsupported.items():
                all_unsupported.setdefault(m, set()).add(name)
            if result is None and status == "ok":
                err = f"{started} Event starts"
            rows.append((source, name, verdict, err, wall, result))
            print(f"{source}/{name}: {verdict} {err}", file=sys.stderr)

    counts = {}
    for r in rows:
        counts[r[2]] = counts.get(r[2], 0) + 1
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                            capture_output=True, text=True).stdout.strip()
    out = []
    out.append("# Conformance report\n")
    out.append("Generated by `python3 scripts/conformance.py` (do not edit by hand; reasons live in "
               "`docs/conformance-notes.tsv`).\n")
    out.append(f"oscsim built from the working tree at commit {commit or 'unknown'}, "
               f"{datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')}; "
               "`oscsim run --dt 0.05`; reference: esmini 3.6.0 "
               "(`../shared/corpus/reference/esmini`), compared by `../shared/tools/compare_run.py` "
               "with tolerances 0.10 m, 0.10 m/s, 0.05 s on event start times.\n")
    out.append("Outcome: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) +
               f" of {len(rows)} scenarios.\n")
    out.append("| scenario | outcome | worst position error (m) | worst speed error (m/s) | "
               "events disagreeing | reason |")
    out.append("| --- | --- | ---: | ---: | --- | --- |")
    for source, name, verdict, err, wall, result in rows:
        if result:
            pos, speed = f"{result['pos']:.3f}", f"{result['speed']:.3f}"
            ev = "; ".join(result["events"]) or "none"
            if result["entities"] and not result["events"]:
                ev = "none (entities off: " + ", ".join(result["entities"]) + ")"
        else:
            pos = speed = "–"
            ev = err or "–"
        reason = notes.get(name, "")
        out.append(f"| {source}/{name} | {verdict} | {pos} | {speed} | {cell(ev)} | {cell(reason)} |")
    readings = read_readings()
    if readings:
        out.append("\nReadings where the motions differ or the standard is silent (issue 34; from "
                   "`docs/conformance-readings.tsv`). Where the standard is silent oscsim follows "
                   "esmini's de-facto behaviour unless it contradicts the text; where esmini departs "
                   "from the text the text wins.\n")
        out.append("| motion | the standard | esmini | oscsim | test |")
        out.append("| --- | --- | --- | --- | --- |")
        for r in readings:
            r = (r + ["", "", "", "", ""])[:5]
            out.append("| " + " | ".join(cell(c) for c in r) + " |")
    examples = read_readings(EXAMPLES)
    if examples:
        out.append("\nASAM's own examples of OpenSCENARIO 1.2 and 1.3 (from "
                   "`docs/conformance-asam-examples.tsv`): the files are not in the repository "
                   "(no licence statement for redistribution in most of them); equivalents written "
                   "for the project keep the constructs each depends on.\n")
        out.append("| example | constructs | equivalent |")
        out.append("| --- | --- | --- |")
        for r in examples:
            r = (r + ["", "", ""])[:3]
            out.append("| " + " | ".join(cell(c) for c in r) + " |")
    if all_unsupported:
        out.append("\nReported as unsupported or as an error in the event logs (conditions and "
                   "actions that read false or did nothing; message: scenarios):\n")
        for m, names in sorted(all_unsupported.items(), key=lambda kv: -len(kv[1])):
            out.append(f"- {m}: {', '.join(sorted(names))}")
    if controllers:
        out.append("\nUser controllers (OpenSCENARIO 1.3 §6.6; engine module `controller`). esmini's "
                   "own controllers are not oscsim models: oscsim keeps them off and the default "
                   "controller drives those entities, as in esmini's reference runs (made with "
                   "`--disable_controllers`). None of them is mapped onto an oscsim model: none "
                   "computes what an oscsim model computes (esmini's ACCController follows its own "
                   "speed law, not the constant-time-gap law with ISO 15622 limits of `acc`; its "
                   "ALKS, ghost, reference, interactive, sloppy, SUMO, HID and external controllers "
                   "have no counterpart). Each assignment and activation is in the event log as a "
                   "`controller` record naming the controller, `model` `none`.\n")
        out.append("| scenario | entity: controller | oscsim model | what oscsim does |")
        out.append("| --- | --- | --- | --- |")
        for source, name, found in controllers:
            for (entity, controller), (model, active, notes) in found.items():
                who = f"{entity}: {controller}" if entity else f"{controller} (never activated)"
                if model in ("", "none"):
                    what = ("kept off; the default controller drives, as in the reference"
                            if active else "assigned, never activated; the default controller drives")
                    model = "none"
                else:
                    what = "; ".join(notes) or ("runs" if active else "assigned, never activated")
                out.append(f"| {source}/{name} | {cell(who)} | {model} | {cell(what)} |")
    if report is None:
        for source, name, verdict, err, wall, result in rows:
            extra = f" pos {result['pos']:.3f} speed {result['speed']:.3f} events {result['events']} entities {result['entities']}" if result else ""
            print(f"{source}/{name}: {verdict}{extra}")
        return
    with open(report, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
    print(f"wrote {os.path.relpath(report, ROOT)}", file=sys.stderr)


if __name__ == "__main__":
    main()
