#!/usr/bin/env python3
"""Driver-model traffic on the scale highway, for oscsim and for Eclipse SUMO (issue 31).

Reads a scenario written by ../shared/tools/make_scale.py (N vehicles on one straight 20 km road,
4 lanes each way; vehicle v{i} in lane -(1 + i mod 4) at s = 100 + 15*(i // 4) m, 20 + (i mod 7)
m/s) and writes:

  oscsim IN.xosc MODEL OUT.xosc
      the same scenario with every vehicle given the built-in driver MODEL (idm, mobil) by an
      ObjectController, activated in the Init after its SpeedAction (so each driver's desired
      speed is its start speed): longitudinal for idm, longitudinal and lateral for mobil.
  sumo IN.xosc MODEL DURATION OUTDIR
      a SUMO run of the same traffic: the road of the scenario's .xodr imported by netconvert
      (its four right-hand lanes are SUMO lanes 0..3, lane -4 = 0), one vehicle per scenario
      vehicle with the same lane, position, speed and size, IDM with the model's defaults
      (accel 0.73, decel 1.67, tau 1.6, minGap 2, delta 4) and desired speed = start speed,
      lane changes by LC2013 (MODEL mobil) or none (MODEL idm), step 0.05 s, DURATION s.
      Writes OUTDIR/highway.net.xml, OUTDIR/traffic.rou.xml, OUTDIR/run.sumocfg.

scripts/sumo_side_by_side.sh runs both; docs/performance.md explains the figures.
"""
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

# The IDM defaults of crates/engine/src/models/idm.rs (Treiber et al. 2000, highway set).
IDM = {"accel": 0.73, "decel": 1.67, "tau": 1.6, "minGap": 2.0, "delta": 4}


def vehicles(xosc):
    """(name, lane id, s, speed, length, width, reference point to front) per Init Private."""
    root = ET.parse(xosc).getroot()
    boxes = {}
    for obj in root.iter("ScenarioObject"):
        box = obj.find("Vehicle/BoundingBox")
        c, d = box.find("Center"), box.find("Dimensions")
        length = float(d.get("length"))
        boxes[obj.get("name")] = (length, float(d.get("width")), float(c.get("x")) + length / 2)
    out = []
    for p in root.iter("Private"):
        name = p.get("entityRef")
        lane = p.find(".//TeleportAction/Position/LanePosition")
        speed = p.find(".//SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed")
        out.append((name, int(lane.get("laneId")), float(lane.get("s")), float(speed.get("value")), *boxes[name]))
    return root, out


def oscsim(xosc_in, model, xosc_out):
    tree = ET.parse(xosc_in)
    root = tree.getroot()
    for obj in root.iter("ScenarioObject"):
        oc = ET.SubElement(obj, "ObjectController", name="driver")
        ctrl = ET.SubElement(oc, "Controller", name="driver")
        props = ET.SubElement(ctrl, "Properties")
        ET.SubElement(props, "Property", name="model", value=model)
    lateral = "true" if model == "mobil" else "false"
    for p in root.iter("Private"):
        action = ET.SubElement(p, "PrivateAction")
        ca = ET.SubElement(action, "ControllerAction")
        ET.SubElement(ca, "ActivateControllerAction", longitudinal="true", lateral=lateral)
    Path(xosc_out).parent.mkdir(parents=True, exist_ok=True)
    logic = root.find("RoadNetwork/LogicFile")
    # Keep the road where it was: the path is relative to the scenario's folder.
    road = (Path(xosc_in).parent / logic.get("filepath")).resolve()
    logic.set("filepath", str(road))
    tree.write(xosc_out, encoding="utf-8", xml_declaration=True)


def sumo(xosc_in, model, duration, outdir):
    root, vs = vehicles(xosc_in)
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    xodr = (Path(xosc_in).parent / root.find("RoadNetwork/LogicFile").get("filepath")).resolve()
    net = outdir / "highway.net.xml"
    subprocess.run(["netconvert", "--opendrive-files", str(xodr), "-o", str(net),
                    "--no-turnarounds", "true", "--speed.minimum", "70",
                    "--opendrive.import-all-lanes", "false"],
                   check=True, stdout=subprocess.DEVNULL)
    # The edge of the right-hand lanes (driving +s): the one whose lanes run +x.
    edge = None
    for e in ET.parse(net).getroot().iter("edge"):
        if e.get("function") == "internal":
            continue
        lanes = e.findall("lane")
        shape = [tuple(map(float, p.split(","))) for p in lanes[0].get("shape").split()]
        if shape[-1][0] > shape[0][0] and len(lanes) == 4:
            edge = e.get("id")
    if edge is None:
        sys.exit("traffic_scale.py: no 4-lane edge driving +x in " + str(net))
    # idm changes no lanes: LC2013 with each of its motives switched off.
    no_changes = {} if model == "mobil" else dict(lcStrategic="-1", lcCooperative="-1", lcSpeedGain="0",
                                                  lcKeepRight="0")
    routes = ET.Element("routes")
    speeds = sorted({v[3] for v in vs})
    for sp in speeds:
        v = vs[0]
        ET.SubElement(routes, "vType", id=f"d{sp:g}", vClass="passenger", length=f"{v[4]:g}", width=f"{v[5]:g}",
                      carFollowModel="IDM", laneChangeModel="LC2013", maxSpeed=f"{sp:g}", speedFactor="1",
                      speedDev="0", sigma="0", emergencyDecel="10", minGap=f"{IDM['minGap']:g}",
                      accel=f"{IDM['accel']:g}", decel=f"{IDM['decel']:g}", tau=f"{IDM['tau']:g}",
                      delta=f"{IDM['delta']}", **no_changes)
    ET.SubElement(routes, "route", id="r", edges=edge)
    for name, lane, s, speed, length, width, front in sorted(vs, key=lambda v: int(v[0][1:])):
        attrs = dict(id=name, type=f"d{speed:g}", route="r", depart="0", departLane=str(4 + lane),
                     departPos=f"{s + front:.3f}", departSpeed=f"{speed:g}", insertionChecks="none")
        ET.SubElement(routes, "vehicle", **attrs)
    ET.ElementTree(routes).write(outdir / "traffic.rou.xml", encoding="utf-8", xml_declaration=True)
    cfg = ET.Element("configuration")
    inp = ET.SubElement(cfg, "input")
    ET.SubElement(inp, "net-file", value=net.name)
    ET.SubElement(inp, "route-files", value="traffic.rou.xml")
    t = ET.SubElement(cfg, "time")
    ET.SubElement(t, "begin", value="0")
    ET.SubElement(t, "end", value=f"{duration:g}")
    ET.SubElement(t, "step-length", value="0.05")
    proc = ET.SubElement(cfg, "processing")
    ET.SubElement(proc, "collision.action", value="none")
    ET.SubElement(proc, "time-to-teleport", value="-1")
    rep = ET.SubElement(cfg, "report")
    ET.SubElement(rep, "no-step-log", value="true")
    ET.SubElement(rep, "no-warnings", value="true")
    ET.SubElement(rep, "duration-log.statistics", value="true")
    ET.ElementTree(cfg).write(outdir / "run.sumocfg", encoding="utf-8", xml_declaration=True)


if __name__ == "__main__":
    cmd = sys.argv[1:2]
    if cmd == ["oscsim"] and len(sys.argv) == 5:
        oscsim(sys.argv[2], sys.argv[3], sys.argv[4])
    elif cmd == ["sumo"] and len(sys.argv) == 6:
        sumo(sys.argv[2], sys.argv[3], float(sys.argv[4]), sys.argv[5])
    else:
        sys.exit(__doc__)
