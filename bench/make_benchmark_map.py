#!/usr/bin/env python3
"""Writes a land-cover map for bench/outputs-batch.sh and prints the mcpp flags that plan it.

    make_benchmark_map.py uniform SIDE ROBOTS FOLDER
        SIDE x SIDE pixels of 10 m, one class with a 5 m field of view (so a pixel is one planning cell),
        15% obstacle pixels and ROBOTS starts at free pixel centres, both drawn with a fixed seed.
    make_benchmark_map.py crowded SIDE ROBOTS WINDOW SEED FOLDER
        The uniform map of SIDE with ROBOTS starts crowded on the free pixels of one WINDOW x WINDOW square
        (robots setting off from one base), square and starts drawn with SEED.
    make_benchmark_map.py forest SIDE ROBOTS FOLDER
        SIDE x SIDE pixels of 10 m of forest (5 m field of view: one planning cell per pixel, the most cells a
        map of that size can have) with 60 x 60-pixel lakes every 300 pixels; starts spread over the map.
    make_benchmark_map.py blocks COLUMNS ROWS ROBOTS FOLDER
        COLUMNS x ROWS pixels of 2.5 m in blocks of 100 x 100 pixels of the synthetic sample's four classes
        (forest 5 m, shrubland 10 m, grassland 20 m field of view; lakes impassable); starts in
        grassland blocks spread over the map.

The map is a raw band with an ESRI .hdr header and a .prj (WGS 84 / UTM zone 33N), turned into a tiled,
compressed GeoTIFF with gdal_translate, the way users' land-cover files come. Pure Python; deterministic.
"""

import os
import random
import subprocess
import sys

WEST = 431000.0
NORTH = 5400000.0
# WGS 84 / UTM zone 33N, in the ESRI flavour GDAL reads beside a raw band: the synthetic sample's own.
PROJECTION = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "samples", "synthetic",
                               "synthetic.prj"), encoding="ascii").read().strip()
CLASSES = """value,name,speed_mps,fov_m,passable,color
1,Dense forest,0.8,5,true,#2e7d32
2,Shrubland,1.5,10,true,#a5a05a
3,Grassland,3,20,true,#d4e157
4,Lake,0,10,false,#4f8fd6
"""
FOREST, SHRUBLAND, GRASSLAND, LAKE = 1, 2, 3, 4
BLOCK = 100


def write_map(folder, name, columns, rows, pixel, row_bytes):
    os.makedirs(folder, exist_ok=True)
    raw = os.path.join(folder, name + ".bil")
    with open(raw, "wb") as band:
        for row in range(rows):
            band.write(row_bytes(row))
    with open(os.path.join(folder, name + ".hdr"), "w", encoding="ascii") as header:
        header.write(
            f"ncols {columns}\nnrows {rows}\nnbands 1\nnbits 8\npixeltype unsignedint\nbyteorder I\n"
            f"layout bil\nulxmap {WEST + pixel / 2}\nulymap {NORTH - pixel / 2}\nxdim {pixel}\n"
            f"ydim {pixel}\nnodata 0\n"
        )
    with open(os.path.join(folder, name + ".prj"), "w", encoding="ascii") as projection:
        projection.write(PROJECTION + "\n")
    tif = os.path.join(folder, name + ".tif")
    subprocess.run(
        ["gdal_translate", "-q", "-of", "GTiff", "-co", "TILED=YES", "-co", "COMPRESS=DEFLATE", raw, tif],
        check=True,
    )
    for extension in (".bil", ".hdr", ".prj"):
        os.remove(os.path.join(folder, name + extension))
    with open(os.path.join(folder, "classes.csv"), "w", encoding="ascii") as table:
        table.write(CLASSES)
    return tif


def uniform(side, robots, folder):
    generator = random.Random(2020 + side * 100 + robots)
    grid = [[LAKE if generator.random() < 0.15 else FOREST for _ in range(side)] for _ in range(side)]
    free = [(column, row) for row in range(side) for column in range(side) if grid[row][column] == FOREST]
    starts = generator.sample(free, robots)
    tif = write_map(folder, f"uniform_{side}", side, side, 10.0, lambda row: bytes(grid[row]))
    return tif, [(WEST + (c + 0.5) * 10.0, NORTH - (r + 0.5) * 10.0) for c, r in starts]


def crowded(side, robots, window, seed, folder):
    tif, _ = uniform(side, robots, folder)
    generator = random.Random(2020 + side * 100 + robots)
    grid = [[LAKE if generator.random() < 0.15 else FOREST for _ in range(side)] for _ in range(side)]
    chooser = random.Random(seed)
    while True:  # a square with room for every start
        left, top = chooser.randrange(side - window + 1), chooser.randrange(side - window + 1)
        free = [(c, r) for r in range(top, top + window) for c in range(left, left + window)
                if grid[r][c] == FOREST]
        if len(free) >= robots:
            break
    starts = chooser.sample(free, robots)
    return tif, [(WEST + (c + 0.5) * 10.0, NORTH - (r + 0.5) * 10.0) for c, r in starts]


def block_class(block_column, block_row):
    return (FOREST, SHRUBLAND, GRASSLAND, FOREST, SHRUBLAND, LAKE, GRASSLAND)[
        (block_column * 3 + block_row * 5) % 7
    ]


def blocks(columns, rows, robots, folder):
    pixel = 2.5
    block_columns = (columns + BLOCK - 1) // BLOCK
    patterns = {}

    def row_bytes(row):
        block_row = row // BLOCK
        if block_row not in patterns:
            line = bytearray()
            for block_column in range(block_columns):
                line += bytes([block_class(block_column, block_row)]) * BLOCK
            patterns[block_row] = bytes(line[:columns])
        return patterns[block_row]

    tif = write_map(folder, f"blocks_{columns}x{rows}", columns, rows, pixel, row_bytes)
    grassland = [
        (bc, br)
        for br in range(rows // BLOCK)
        for bc in range(columns // BLOCK)
        if block_class(bc, br) == GRASSLAND
    ]
    step = max(1, len(grassland) // robots)
    starts = []
    for i in range(robots):
        bc, br = grassland[(i * step + step // 2) % len(grassland)]
        shift = (i * step // len(grassland)) * 20  # pixels apart when robots share a block
        starts.append((WEST + (bc * BLOCK + 10 + shift) * pixel, NORTH - (br * BLOCK + 50) * pixel))
    return tif, starts


def forest(side, robots, folder):
    plain = bytes([FOREST]) * side
    lakes = bytearray(plain)
    for column in range(100, side, 300):
        lakes[column : column + 60] = bytes([LAKE]) * len(lakes[column : column + 60])
    lakes = bytes(lakes)
    tif = write_map(folder, f"forest_{side}", side, side, 10.0,
                    lambda row: lakes if 100 <= row % 300 < 160 else plain)
    starts = []
    for i in range(robots):
        # On a diagonal, clear of the lakes (which start 100 pixels into every 300).
        pixel = 50 + (i * (side - 100)) // max(1, robots - 1) if robots > 1 else side // 2
        pixel = pixel - pixel % 300 + 50
        if pixel >= side:  # the last start of a side that is a multiple of 300 plus 50
            pixel -= 300
        starts.append((WEST + (pixel + 0.5) * 10.0, NORTH - (pixel + 0.5) * 10.0))
    return tif, starts


def main():
    kind = sys.argv[1]
    if kind == "uniform":
        tif, starts = uniform(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
        folder = sys.argv[4]
    elif kind == "crowded":
        tif, starts = crowded(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]),
                              sys.argv[6])
        folder = sys.argv[6]
    elif kind == "forest":
        tif, starts = forest(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
        folder = sys.argv[4]
    else:
        tif, starts = blocks(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5])
        folder = sys.argv[5]
    flags = [f"--raster {tif}", f"--classes {os.path.join(folder, 'classes.csv')}"]
    flags += [f"--start {x:.2f},{y:.2f}" for x, y in starts]
    print(" ".join(flags))


if __name__ == "__main__":
    main()
