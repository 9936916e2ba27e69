#!/usr/bin/env python3
"""A flat grid of dim ceiling lights over an office floor with partitions, as a levrt scene file
(scenes/README.md): every light adds a little to every point and none dominates, the case where
an absolute tolerance is either slow or wrong and a cut relative to the pixel is not.

    tools/make_dim_ceiling.py --side 100 --out dim_ceiling.json   # 100 x 100 = 10,000 lights
"""
import argparse
import json


def build(side, spacing):
    extent = side * spacing
    height = 3.0
    # Irradiance under an infinite plane of lights of density 1/spacing^2 is 2 pi I / spacing^2
    # (with the floor's cosine): about 0.6 in radiance with kd 0.7, whatever the grid.
    intensity = 0.14 * spacing * spacing
    lights = []
    for i in range(side):
        for j in range(side):
            x = (i + 0.5) * spacing - extent / 2
            y = (j + 0.5) * spacing - extent / 2
            lights.append({"type": "affine", "translate": [round(x, 4), round(y, 4), height],
                           "child": {"type": "point_light", "intensity": [intensity] * 3}})
    children = [
        {"type": "quad", "material": "floor", "corner": [-extent / 2, -extent / 2, 0],
         "edge_u": [extent, 0, 0], "edge_v": [0, extent, 0]},
        {"type": "quad", "material": "ceiling", "corner": [-extent / 2, -extent / 2, height + 0.05],
         "edge_u": [extent, 0, 0], "edge_v": [0, extent, 0]},
    ]
    # Partitions: rows of desk-high and full-height walls across the floor.
    for k in range(-3, 4):
        y = k * extent / 8
        children.append({"type": "box", "material": "wall", "lo": [-extent / 3, y - 0.05, 0],
                         "hi": [extent / 6, y + 0.05, 1.4 if k % 2 else 2.6]})
    for k in range(-2, 3):
        children.append({"type": "sphere", "material": "chrome",
                         "centre": [k * extent / 6, extent / 16, 0.6], "radius": 0.6})
    children.append({"type": "union", "children": lights})
    return {
        "levrt_scene": 1,
        "name": f"dim ceiling {side * side}",
        "camera": {"position": [-extent / 2 + 1, -extent / 2 + 1, 2.2],
                   "target": [0, 0, 0.8], "fov_degrees": 60},
        "ambient": [0.05, 0.05, 0.05],
        "materials": [
            {"name": "floor", "colour": [0.7, 0.7, 0.65], "kd": 0.7},
            {"name": "ceiling", "colour": [0.9, 0.9, 0.9], "kd": 0.6},
            {"name": "wall", "colour": [0.5, 0.6, 0.8], "kd": 0.7, "ks": 0.2, "shininess": 30},
            {"name": "chrome", "colour": [0.8, 0.8, 0.8], "kd": 0.2, "ks": 0.6, "shininess": 80,
             "kr": 0.5},
        ],
        "root": {"type": "union", "children": children},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--side", type=int, default=100, help="lights per side of the grid")
    parser.add_argument("--spacing", type=float, default=0.5, help="between lights")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    with open(args.out, "w") as f:
        json.dump(build(args.side, args.spacing), f)


if __name__ == "__main__":
    main()
