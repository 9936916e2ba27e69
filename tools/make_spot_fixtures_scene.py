#!/usr/bin/env python3
"""A scene file of fixtures of spots aimed apart, for measuring lev_cut's exact clusters off the
built-in models: 144 instances of one master of six coloured spots (each 50 degrees from straight
down, turned 60 degrees apart), placed on a jittered 12x12 grid at heights 8..10 and turned about
z at random, over the stage's floor, boxes and objects (taken from a `levrt export` of the stage).

    levrt export --scene stage --level 3 --out stage.json
    tools/make_spot_fixtures_scene.py stage.json fixtures.json
"""
import json
import math
import os
import random
import sys


def main(stage_path, out_path):
    random.seed(5)
    scene = json.load(open(stage_path))
    geometry = [n for n in scene["root"]["children"] if "light" not in json.dumps(n)]
    colours = [[40, 8, 8], [8, 40, 8], [8, 8, 40], [30, 30, 6], [6, 30, 30], [30, 6, 30]]
    spots = []
    for k in range(6):
        azimuth = math.radians(60.0 * k)
        spots.append({
            "type": "affine",
            "translate": [0.3 * math.cos(azimuth), 0.3 * math.sin(azimuth), 0],
            "rotate": {"axis": [-math.sin(azimuth), math.cos(azimuth), 0], "degrees": 50},
            "child": {"type": "spot_light", "intensity": colours[k], "cone_degrees": 22,
                      "dropoff": 3},
        })
    fixtures = []
    for i in range(12):
        for j in range(12):
            fixtures.append({
                "type": "affine",
                "translate": [-22 + 4 * i + random.uniform(-0.5, 0.5), -12 + 3 * j,
                              8 + random.uniform(0, 2)],
                "rotate": {"axis": [0, 0, 1], "degrees": random.uniform(0, 360)},
                "child": {"type": "instance", "master": "fixture"},
            })
    scene["name"] = "spot fixtures"
    scene["masters"] = [{"name": "fixture", "node": {"type": "union", "children": spots}}]
    scene["root"] = {"type": "union", "children": geometry + fixtures}
    with open(out_path, "w") as f:
        json.dump(scene, f, indent=1)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: make_spot_fixtures_scene.py STAGE_EXPORT.json OUT.json")
    if os.path.exists(sys.argv[2]) and os.path.samefile(sys.argv[1], sys.argv[2]):
        sys.exit("make_spot_fixtures_scene.py: the output is the stage export it reads")
    main(sys.argv[1], sys.argv[2])
