#!/usr/bin/env python3
"""Measures the replay page of a large run in headless Chromium: its size, how long it takes to
open (navigation start to `oscsimReplay.ready`), and the drawing time per frame.

The run: a generated 3 km road with four lanes each way and 200 vehicles driving 60 s at
20-32 m/s, 40 of them changing lanes (written to target/replay_fps/). `oscsim view` turns the
scenario into a page; Chromium is driven over the DevTools protocol on a pipe
(--remote-debugging-pipe: commands on fd 3, answers on fd 4, NUL-separated JSON), in real
time, so the figures are the machine's (not a virtual clock's).

Usage: scripts/replay_fps.py [--oscsim PATH] [--frames N] [--chromium PATH]
Prints one JSON object: html_bytes, open_ms, frames, mean_ms, max_ms, fps (1000 / mean_ms).
A measurement, not a test: the drawing of the frames is what `benchmark(n)` in app.js times.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "target", "replay_fps")

LANE = """<lane id="{id}" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>
<roadMark sOffset="0" type="{mark}" weight="standard" color="standard" width="0.15"/></lane>"""


def road():
    left = "".join(LANE.format(id=i, mark="solid" if i == 4 else "broken") for i in (4, 3, 2, 1))
    right = "".join(LANE.format(id=-i, mark="solid" if i == 4 else "broken") for i in (1, 2, 3, 4))
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE><header revMajor="1" revMinor="6" name="replay_fps"/>
<road id="1" junction="-1" length="3000"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="1000"><line/></geometry>
<geometry s="1000" x="1000" y="0" hdg="0" length="1000"><arc curvature="0.0005"/></geometry>
<geometry s="2000" x="1958.851077208406" y="244.8348762192545" hdg="0.5" length="1000"><line/></geometry>
</planView><lanes><laneSection s="0">
<left>{left}</left>
<center><lane id="0" type="none" level="false"><roadMark sOffset="0" type="solid solid" weight="standard" color="yellow" width="0.15"/></lane></center>
<right>{right}</right>
</laneSection></lanes></road></OpenDRIVE>
"""


def scenario():
    objects, privates, events = [], [], []
    colors = ["red", "blue", "green", "yellow", "white", "grey", "black", "orange"]
    for k in range(200):
        lane = [-1, -2, -3, -4, 1, 2, 3, 4][k % 8]
        slot = k // 8
        s = 40 + 30 * slot if lane < 0 else 2960 - 30 * slot
        speed = 20 + (k * 7) % 13
        name = f"car{k:03d}"
        objects.append(f"""<ScenarioObject name="{name}"><Vehicle name="car" vehicleCategory="car">
<BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="1.9" length="4.6" height="1.5"/></BoundingBox>
<Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.7" trackWidth="1.6" positionX="2.8" positionZ="0.35"/>
<RearAxle maxSteering="0" wheelDiameter="0.7" trackWidth="1.6" positionX="0" positionZ="0.35"/></Axles>
<Properties><Property name="color" value="{colors[k % 8]}"/></Properties></Vehicle></ScenarioObject>""")
        privates.append(f"""<Private entityRef="{name}">
<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction>
<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/>
<SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>""")
        if k % 5 == 0 and abs(lane) in (2, 3):
            events.append(f"""<ManeuverGroup maximumExecutionCount="1" name="g{k}"><Actors selectTriggeringEntities="false"><EntityRef entityRef="{name}"/></Actors>
<Maneuver name="m{k}"><Event name="e{k}" priority="parallel"><Action name="lc{k}"><PrivateAction><LateralAction><LaneChangeAction>
<LaneChangeActionDynamics dynamicsShape="sinusoidal" dynamicsDimension="time" value="3"/>
<LaneChangeTarget><RelativeTargetLane entityRef="{name}" value="1"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction></Action>
<StartTrigger><ConditionGroup><Condition name="c{k}" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="{5 + k % 40}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>""")
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2026-01-01T00:00:00" description="200 vehicles, 60 s" author="scripts/replay_fps.py"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="replay_fps.xodr"/></RoadNetwork>
<Entities>{"".join(objects)}</Entities>
<Storyboard><Init><Actions>{"".join(privates)}</Actions></Init>
<Story name="traffic"><Act name="act">{"".join(events)}</Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="60" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>
"""


class Pipe:
    """The DevTools protocol over --remote-debugging-pipe."""

    def __init__(self, chromium, profile):
        self.to_browser_r, self.to_browser_w = os.pipe()
        self.from_browser_r, self.from_browser_w = os.pipe()

        def fds():
            os.dup2(self.to_browser_r, 3)
            os.dup2(self.from_browser_w, 4)

        args = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--window-size=1400,900", f"--user-data-dir={profile}",
                "--remote-debugging-pipe", "about:blank"]
        # fds 3 and 4 are made in preexec_fn, before the child closes the fds it does not keep.
        self.proc = subprocess.Popen(args, preexec_fn=fds, pass_fds=(3, 4),
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(self.to_browser_r)
        os.close(self.from_browser_w)
        self.buf = b""
        self.next_id = 0

    def call(self, method, params=None, session=None):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.to_browser_w, json.dumps(msg).encode() + b"\0")
        while True:
            while b"\0" not in self.buf:
                chunk = os.read(self.from_browser_r, 1 << 16)
                if not chunk:
                    raise RuntimeError("the browser closed the pipe")
                self.buf += chunk
            line, self.buf = self.buf.split(b"\0", 1)
            reply = json.loads(line)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]

    def close(self):
        try:
            self.call("Browser.close")
        except Exception:
            pass
        self.proc.wait(timeout=10)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--oscsim", default=os.path.join(ROOT, "target", "release", "oscsim"))
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--frames", type=int, default=300)
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "replay_fps.xodr"), "w") as f:
        f.write(road())
    xosc = os.path.join(OUT, "replay_fps.xosc")
    with open(xosc, "w") as f:
        f.write(scenario())
    html = os.path.join(OUT, "replay_fps.html")
    subprocess.run([a.oscsim, "view", xosc, "-o", html], check=True, stdout=subprocess.DEVNULL)
    with tempfile.TemporaryDirectory() as profile:
        b = Pipe(a.chromium, profile)
        try:
            target = b.call("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = b.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            b.call("Page.enable", session=session)
            b.call("Page.navigate", {"url": "file://" + html}, session=session)
            expr = ("(async () => { while (!window.oscsimReplay) await new Promise(r => setTimeout(r, 5));"
                    " await window.oscsimReplay.ready; const open = performance.now();"
                    f" const r = window.oscsimReplay.benchmark({a.frames}); r.open_ms = open; return JSON.stringify(r); }})()")
            res = b.call("Runtime.evaluate", {"expression": expr, "awaitPromise": True, "returnByValue": True},
                         session=session)
            r = json.loads(res["result"]["value"])
        finally:
            b.close()
    print(json.dumps({"html_bytes": os.path.getsize(html), "open_ms": round(r["open_ms"], 1),
                      "frames": r["frames"], "mean_ms": round(r["meanMs"], 2), "max_ms": round(r["maxMs"], 2),
                      "fps": round(r["fps"], 1)}))


if __name__ == "__main__":
    sys.exit(main())
