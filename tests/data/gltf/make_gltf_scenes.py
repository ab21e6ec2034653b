#!/usr/bin/env python3
"""Writes the glTF scenes the tests load (run from this folder; the outputs are committed):

  node-tree.gltf (+ node-tree-external.gltf, node-tree.bin): a chrome cube three nodes deep (TRS,
      quaternion, matrix), a red quad, a camera and a directional KHR_lights_punctual light;
      the buffer embedded as a data: URI, and the same scene with it in an external file.
  chrome-sphere.glb: a closed chrome UV sphere (metallic 1, roughness 0.05) on a floor with a
      checker texture (a PNG in the GLB's buffer, repeated 6 times a side), a red box and a green
      box, a camera looking at it.
  textured-box.gltf (+ crate.png): a box whose six faces each show the whole of an external PNG
      (clamped), on a floor tinted by the same image, mirrored-repeat; no camera, no lights.
  animated.glb: a chrome sphere bobbing over a floor while a red box circles it (a carousel node turned
      by LINEAR rotation keys), a green box halves in size at 1 s (STEP scale) and a blue box crosses in
      front (CUBICSPLINE translation), all in the animation "show" (2 s); the camera dollies in over 4 s
      in the animation "dolly".
  open-chrome.glb: open chrome meshes, two-sided mirrors: a bowl (a sphere's lower half, no lid) and a
      half-pipe panel (half a cylinder's side, no caps) on a floor between a red box in front and a green
      box behind, a camera looking down at them from the front.
  morphing.glb: a chrome sphere between two objects whose morph targets animate (animation "wave",
      2 s): a cloth left of it, facing it (a 24 x 16 grid, weights [0.2, 0] on its node) waving with one target
      and bulging with the other, by LINEAR weight keys, and a red box whose top rises by one
      CUBICSPLINE weight (zero tangents: a smoothstep) from 0 at 0 s to 1 at 2 s.
  skinned.glb: a chrome sphere beside an arm (a tube 2 m tall, 12 sides, 16 rings) skinned to two
      joints: "shoulder" at its base (1.3, 0, 1.4), front right of the sphere, turning about y by 0-90 degrees (LINEAR, 2 s), and its child
      "elbow" 1 m up, bending about z by 0-60-0 degrees (LINEAR); vertices below 0.75 m follow the
      shoulder, above 1.25 m the elbow, blended linearly between (JOINTS_0 as bytes, WEIGHTS_0 floats).
      The arm's own node has a translation glTF says a skinned mesh ignores.
  deforming-mirrors.glb: mirrors that change shape, in the animation "squash and bend" (2 s): a chrome
      sphere squashed by one morph target (LINEAR weight 0-1-0) and a chrome arm, skinned as skinned.glb's,
      swinging and bending; a red, a green and a blue box round them to reflect.
  engine.glb: a two-cylinder engine of 29 meshes on 82 nodes up to five deep (TRS and matrices,
      meshes instanced on several nodes), painted, cast, aluminium, rubber, copper and chrome parts
      (the chrome valve covers, exhaust headers, flywheel and oil cap become mirrors), two
      KHR_lights_punctual lights, no camera: the multi-part CAD model a glTF viewer opens, made
      here because the public one (Khronos' 2CylinderEngine) cannot be fetched on this machine.
"""
import base64, json, math, struct, zlib


def pack(floats=(), ints=()):
    return struct.pack("<%df" % len(floats), *floats) + struct.pack("<%dI" % len(ints), *ints)


class Builder:
    def __init__(self):
        self.bin = b""
        self.doc = {"asset": {"version": "2.0", "generator": "specula tests/data/gltf/make_gltf_scenes.py"},
                    "buffers": [], "bufferViews": [], "accessors": [], "meshes": [], "materials": [],
                    "nodes": [], "scenes": [], "scene": 0}

    def accessor(self, data, kind, count, component, minmax=None):
        while len(self.bin) % 4:
            self.bin += b"\0"
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        self.bin += data
        self.doc["bufferViews"].append(view)
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component, "count": count, "type": kind}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, positions, normals, indices, material, uvs=None, targets=(), weights=None):
        """A one-primitive mesh; `targets` are morph targets, each (position deltas, normal deltas)."""
        flat = [c for p in positions for c in p]
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        pos = self.accessor(pack(flat), "VEC3", len(positions), 5126, (lo, hi))
        nor = self.accessor(pack([c for n in normals for c in n]), "VEC3", len(normals), 5126)
        ind = self.accessor(pack(ints=indices), "SCALAR", len(indices), 5125)
        attributes = {"POSITION": pos, "NORMAL": nor}
        if uvs:
            attributes["TEXCOORD_0"] = self.accessor(pack([c for uv in uvs for c in uv]), "VEC2", len(uvs), 5126)
        primitive = {"attributes": attributes, "indices": ind, "material": material}
        if targets:
            primitive["targets"] = [
                {"POSITION": self.accessor(pack([c for d in dp for c in d]), "VEC3", len(dp), 5126,
                                           ([min(d[i] for d in dp) for i in range(3)],
                                            [max(d[i] for d in dp) for i in range(3)])),
                 "NORMAL": self.accessor(pack([c for d in dn for c in d]), "VEC3", len(dn), 5126)}
                for dp, dn in targets]
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        if weights is not None:
            self.doc["meshes"][-1]["weights"] = weights
        return len(self.doc["meshes"]) - 1

    def material(self, name, rgb, metallic, roughness, texture=None):
        pbr = {"baseColorFactor": list(rgb) + [1.0], "metallicFactor": metallic, "roughnessFactor": roughness}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        self.doc["materials"].append({"name": name, "pbrMetallicRoughness": pbr})
        return len(self.doc["materials"]) - 1

    def texture(self, image, wrap):
        """A texture of image `image` (an index) with a sampler wrapping both ways by `wrap` (GL's enum)."""
        self.doc.setdefault("samplers", []).append({"wrapS": wrap, "wrapT": wrap})
        self.doc.setdefault("textures", []).append({"source": image, "sampler": len(self.doc["samplers"]) - 1})
        return len(self.doc["textures"]) - 1

    def embedded_image(self, png):
        """An image stored in the binary buffer (GLB)."""
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(png)})
        self.bin += png
        self.doc.setdefault("images", []).append({"bufferView": len(self.doc["bufferViews"]) - 1, "mimeType": "image/png"})
        return len(self.doc["images"]) - 1

    def animation(self, name, channels):
        """An animation of `channels`, each (node, path, interpolation, times, values as flat floats)."""
        samplers, targets = [], []
        for node, path, interpolation, times, values in channels:
            kind = {"rotation": "VEC4", "weights": "SCALAR"}.get(path, "VEC3")
            width = {"VEC4": 4, "SCALAR": 1}.get(kind, 3)
            times_at = self.accessor(pack(times), "SCALAR", len(times), 5126, ([min(times)], [max(times)]))
            values_at = self.accessor(pack(values), kind, len(values) // width, 5126)
            samplers.append({"input": times_at, "output": values_at, "interpolation": interpolation})
            targets.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})
        self.doc.setdefault("animations", []).append({"name": name, "channels": targets, "samplers": samplers})

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        return len(self.doc["nodes"]) - 1

    def finish(self):
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.doc["buffers"] = [{"byteLength": len(self.bin)}]

    def write_glb(self, name):
        """Finishes the buffer and writes the document and it as a GLB container."""
        self.finish()
        text = json.dumps(self.doc).encode()
        text += b" " * (-len(text) % 4)
        length = 12 + 8 + len(text) + 8 + len(self.bin)
        with open(name, "wb") as f:
            f.write(b"glTF" + struct.pack("<II", 2, length) + struct.pack("<I", len(text)) + b"JSON" + text)
            f.write(struct.pack("<I", len(self.bin)) + b"BIN\0" + self.bin)


REPEAT, CLAMP, MIRRORED_REPEAT = 10497, 33071, 33648


def png(width, height, pixel):
    """An RGB PNG whose texel (x, y), row 0 at the top, is pixel(x, y) = (r, g, b) bytes."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def checker_png():
    """64 x 64 texels, 8 x 8 cells of warm white and slate blue."""
    return png(64, 64, lambda x, y: (235, 225, 200) if (x // 8 + y // 8) % 2 == 0 else (40, 60, 110))


def crate_png():
    """32 x 32 texels: an orange frame around a quartered centre (red, green / blue, yellow), so
    a face's orientation shows."""
    def pixel(x, y):
        if min(x, y, 31 - x, 31 - y) < 4:
            return (220, 130, 30)
        return [[(200, 40, 40), (40, 170, 60)], [(40, 70, 200), (230, 210, 40)]][y // 16][x // 16]
    return png(32, 32, pixel)


def box(half):
    """A closed box: 24 vertices (flat normals), 12 triangles, fronts outwards; uv covers each face once."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            corners = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sign * half[axis], a * half[u], b * half[v]
                corners.append(p)
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            base = len(positions)
            positions += corners
            normals += [n] * 4
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            indices += [base + i for i in quad]
    return positions, normals, indices


def box_uvs():
    return [[0, 1], [1, 1], [1, 0], [0, 0]] * 6


def sphere(radius, rings, segments):
    """A closed UV sphere with shared seam and pole vertices, fronts outwards."""
    positions, normals = [[0.0, radius, 0.0]], [[0.0, 1.0, 0.0]]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
    positions.append([0.0, -radius, 0.0])
    normals.append([0.0, -1.0, 0.0])
    south = len(positions) - 1
    at = lambda r, s: 1 + (r - 1) * segments + s % segments
    indices = []
    for s in range(segments):
        indices += [0, at(1, s), at(1, s + 1)]
        indices += [south, at(rings - 1, s + 1), at(rings - 1, s)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b, c, d = at(r, s), at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)
            indices += [a, c, d, a, d, b]
    return positions, normals, indices


def cylinder(radius, height, slices, axis=1):
    """A closed cylinder about the origin along `axis` (0 x, 1 y, 2 z): side with smooth normals,
    flat caps; fronts outwards."""
    positions, normals, indices = [], [], []
    def place(r, y, c):  # radial (r along the first free axis, c the second), height y
        p = [0.0, 0.0, 0.0]
        u, v = (axis + 1) % 3, (axis + 2) % 3
        p[u], p[axis], p[v] = r[0], y, r[1]
        return p
    ring = [(math.cos(2 * math.pi * i / slices), math.sin(2 * math.pi * i / slices)) for i in range(slices)]
    for y in (-height / 2, height / 2):
        for c, s_ in ring:
            positions.append(place((radius * c, radius * s_), y, None))
            normals.append(place((c, s_), 0.0, None))
    for i in range(slices):
        j = (i + 1) % slices
        indices += [i, j, slices + j, i, slices + j, slices + i]
    for cap, y in ((0, -height / 2), (1, height / 2)):
        centre = len(positions)
        n = place((0.0, 0.0), 1.0 if cap else -1.0, None)
        positions.append(place((0.0, 0.0), y, None))
        normals.append(n)
        first = len(positions)
        for c, s_ in ring:
            positions.append(place((radius * c, radius * s_), y, None))
            normals.append(n)
        for i in range(slices):
            j = (i + 1) % slices
            indices += [centre, first + i, first + j] if cap else [centre, first + j, first + i]
    return positions, normals, indices


def torus(major, minor, majors, minors):
    """A closed torus about the y axis; fronts outwards."""
    positions, normals, indices = [], [], []
    for i in range(majors):
        a = 2 * math.pi * i / majors
        for j in range(minors):
            b = 2 * math.pi * j / minors
            n = [math.cos(b) * math.cos(a), math.sin(b), -math.cos(b) * math.sin(a)]
            positions.append([(major + minor * math.cos(b)) * math.cos(a), minor * math.sin(b), -(major + minor * math.cos(b)) * math.sin(a)])
            normals.append(n)
    at = lambda i, j: (i % majors) * minors + j % minors
    for i in range(majors):
        for j in range(minors):
            indices += [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)]
    return positions, normals, indices


def quad(half):
    return ([[-half, 0, -half], [half, 0, -half], [half, 0, half], [-half, 0, half]],
            [[0, 1, 0]] * 4, [0, 2, 1, 0, 3, 2])


def quad_uvs(repeats):
    return [[0, 0], [repeats, 0], [repeats, repeats], [0, repeats]]


def node_tree():
    g = Builder()
    chrome = g.material("chrome", (0.9, 0.9, 0.9), 1.0, 0.05)
    red = g.material("red", (0.8, 0.1, 0.1), 0.0, 0.6)
    cube = g.mesh("cube", *box((0.5, 0.5, 0.5)), chrome)
    floor = g.mesh("quad", *quad(4.0), red)
    s = math.sqrt(0.5)
    grandchild = g.node(name="cube", mesh=cube, matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1])
    child = g.node(name="child", translation=[0, 1, 0], scale=[2, 2, 2], children=[grandchild])
    root = g.node(name="root", translation=[1, 0, 0], rotation=[0, s, 0, s], children=[child])
    ground = g.node(name="ground", mesh=floor, translation=[0, -1, 0])
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "aspectRatio": 1.333}}]
    camera = g.node(name="camera", camera=0, translation=[7, 3, 12])
    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    sun = g.node(name="sun", rotation=[-0.3826834, 0, 0, 0.9238795], extensions={"KHR_lights_punctual": {"light": 0}})
    g.doc["scenes"] = [{"nodes": [root, ground, camera, sun]}]
    g.finish()
    embedded = dict(g.doc)
    embedded["buffers"] = [{"byteLength": len(g.bin),
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(g.bin).decode()}]
    with open("node-tree.gltf", "w") as f:
        json.dump(embedded, f, indent=1)
    external = dict(g.doc)
    external["buffers"] = [{"byteLength": len(g.bin), "uri": "node-tree.bin"}]
    with open("node-tree-external.gltf", "w") as f:
        json.dump(external, f, indent=1)
    with open("node-tree.bin", "wb") as f:
        f.write(g.bin)


def chrome_sphere():
    g = Builder()
    chrome = g.material("chrome", (1.0, 1.0, 1.0), 1.0, 0.05)
    grey = g.material("floor", (0.9, 0.9, 0.9), 0.0, 0.8, texture=g.texture(g.embedded_image(checker_png()), REPEAT))
    red = g.material("red", (0.8, 0.08, 0.05), 0.0, 0.5)
    green = g.material("green", (0.1, 0.6, 0.15), 0.0, 0.5)
    ball = g.mesh("sphere", *sphere(1.0, 48, 96), chrome)
    floor = g.mesh("floor", *quad(6.0), grey, uvs=quad_uvs(6))
    red_box = g.mesh("red box", *box((0.6, 0.6, 0.6)), red)
    green_box = g.mesh("green box", *box((0.4, 0.9, 0.4)), green)
    nodes = [g.node(name="sphere", mesh=ball, translation=[0, 1, 0]),
             g.node(name="floor", mesh=floor),
             g.node(name="red box", mesh=red_box, translation=[2.2, 0.6, 0.8]),
             g.node(name="green box", mesh=green_box, translation=[-1.8, 0.9, 1.5])]
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1}}]
    # Looks from (0, 2.5, 6) down at the sphere: a rotation of -0.25 rad about x.
    nodes.append(g.node(name="camera", camera=0, translation=[0, 2.5, 6], rotation=[-0.1243503, 0, 0, 0.9922385]))
    g.doc["scenes"] = [{"nodes": nodes}]
    g.write_glb("chrome-sphere.glb")


def textured_box():
    g = Builder()
    g.doc["images"] = [{"uri": "crate.png"}]
    crate = g.material("crate", (1.0, 1.0, 1.0), 0.0, 0.7, texture=g.texture(0, CLAMP))
    tinted = g.material("tinted floor", (0.6, 0.6, 0.6), 0.0, 0.9, texture=g.texture(0, MIRRORED_REPEAT))
    cube = g.mesh("crate", *box((0.5, 0.5, 0.5)), crate, uvs=box_uvs())
    floor = g.mesh("floor", *quad(3.0), tinted, uvs=quad_uvs(3))
    g.doc["scenes"] = [{"nodes": [g.node(name="crate", mesh=cube, translation=[0, 0.5, 0], rotation=[0, 0.3826834, 0, 0.9238795]),
                                  g.node(name="floor", mesh=floor)]}]
    g.finish()
    g.doc["buffers"] = [{"byteLength": len(g.bin),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(g.bin).decode()}]
    with open("textured-box.gltf", "w") as f:
        json.dump(g.doc, f, indent=1)
    with open("crate.png", "wb") as f:
        f.write(crate_png())


def camera_looking_down(g, yfov, translation, degrees):
    """The file's one perspective camera on a node at `translation`, tilted `degrees` down about x."""
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": yfov, "znear": 0.1}}]
    tilt = math.radians(-degrees) / 2
    return g.node(name="camera", camera=0, translation=translation, rotation=[math.sin(tilt), 0, 0, math.cos(tilt)])


def bowl(radius, rings, segments):
    """A sphere's lower half, open at the equator: smooth normals outwards, fronts outwards."""
    positions, normals = [], []
    for r in range(rings + 1):
        theta = math.pi / 2 + math.pi / 2 * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
    indices = []
    for r in range(rings):
        for s in range(segments):
            a, b = r * segments + s, r * segments + (s + 1) % segments
            c, d = a + segments, b + segments
            indices += [a, c, d, a, d, b]
    return positions, normals, indices


def half_pipe(radius, height, slices):
    """Half a cylinder's side about y (x ≥ 0 turned to face +z), no caps: normals outwards."""
    positions, normals, indices = [], [], []
    for y in (-height / 2, height / 2):
        for i in range(slices + 1):
            a = math.pi * i / slices
            n = [math.cos(a), 0.0, math.sin(a)]
            positions.append([radius * n[0], y, radius * n[2]])
            normals.append(n)
    for i in range(slices):
        top = slices + 1
        indices += [i, i + 1 + top, i + 1, i, i + top, i + 1 + top]
    return positions, normals, indices


def open_chrome():
    g = Builder()
    chrome = g.material("chrome", (0.95, 0.95, 0.95), 1.0, 0.02)
    grey = g.material("floor", (0.45, 0.5, 0.55), 0.0, 0.8)
    red = g.material("red", (0.8, 0.1, 0.1), 0.0, 0.6)
    green = g.material("green", (0.1, 0.7, 0.2), 0.0, 0.6)
    nodes = [
        g.node(name="bowl", mesh=g.mesh("bowl", *bowl(1.0, 12, 48), chrome), translation=[-1.4, 1.1, 0]),
        g.node(name="panel", mesh=g.mesh("panel", *half_pipe(0.9, 1.6, 48), chrome), translation=[1.4, 0.8, 0]),
        g.node(name="floor", mesh=g.mesh("floor", *quad(5.0), grey)),
        g.node(name="red box", mesh=g.mesh("red box", *box((0.4, 0.4, 0.4)), red), translation=[0.2, 0.4, 2.2]),
        g.node(name="green box", mesh=g.mesh("green box", *box((0.5, 0.5, 0.5)), green), translation=[0, 0.5, -2.5]),
    ]
    nodes.append(camera_looking_down(g, 0.7, [0, 3.2, 7], 22.0))
    g.doc["scenes"] = [{"nodes": nodes}]
    g.write_glb("open-chrome.glb")


# The materials several scenes share, by name: (base colour, metallic, roughness).
MATERIALS = {
    "chrome": ((0.9, 0.9, 0.9), 1.0, 0.05),
    "floor": ((0.45, 0.5, 0.55), 0.0, 0.8),
    "red": ((0.8, 0.1, 0.1), 0.0, 0.6),
    "green": ((0.1, 0.7, 0.2), 0.0, 0.6),
    "blue": ((0.1, 0.2, 0.8), 0.0, 0.6),
}


def materials(g, *names):
    """The named shared materials, added to `g` in that order; their indices."""
    return [g.material(name, *MATERIALS[name]) for name in names]


def animated():
    g = Builder()
    chrome, grey, red, green, blue = materials(g, "chrome", "floor", "red", "green", "blue")
    ball = g.mesh("ball", *sphere(1.0, 24, 48), chrome)
    floor = g.mesh("floor", *quad(5.0), grey)
    cube = lambda name, material: g.mesh(name, *box((0.4, 0.4, 0.4)), material)
    mirror = g.node(name="mirror", mesh=ball, translation=[0, 1.2, 0])
    red_box = g.node(name="red box", mesh=cube("red box", red), translation=[2.5, 0.4, 0])
    carousel = g.node(name="carousel", children=[red_box])
    green_box = g.node(name="green box", mesh=cube("green box", green), translation=[-2.5, 0.4, -2.6])
    blue_box = g.node(name="blue box", mesh=cube("blue box", blue), translation=[-1.5, 0.4, 2.6])
    ground = g.node(name="floor", mesh=floor)
    camera = camera_looking_down(g, 0.8, [0, 3, 9], 15.0)
    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    sun = g.node(name="sun", rotation=[-0.3826834, 0.2, 0, 0.9], extensions={"KHR_lights_punctual": {"light": 0}})
    turn = lambda degrees: [0, math.sin(math.radians(degrees) / 2), 0, math.cos(math.radians(degrees) / 2)]
    g.animation("show", [
        (mirror, "translation", "LINEAR", [0, 1, 2], [0, 1.2, 0, 0, 1.7, 0, 0, 1.2, 0]),
        (carousel, "rotation", "LINEAR", [0, 2 / 3, 4 / 3, 2], turn(0) + turn(120) + turn(240) + turn(360)),
        (green_box, "scale", "STEP", [0, 1], [1, 1, 1, 0.5, 0.5, 0.5]),
        # (in-tangent, value, out-tangent) a key: x tangents of the straight line, y tangents of 1 make a hump.
        (blue_box, "translation", "CUBICSPLINE", [0, 2],
         [0, 1, 0, -1.5, 0.4, 2.6, 1.5, 1, 0] + [1.5, 1, 0, 1.5, 0.4, 2.6, 0, 1, 0]),
    ])
    g.animation("dolly", [(camera, "translation", "LINEAR", [0, 4], [0, 3, 9, 0, 3, 7])])
    g.doc["scenes"] = [{"nodes": [ground, mirror, carousel, green_box, blue_box, camera, sun]}]
    g.write_glb("animated.glb")


def cloth(width, height, columns, rows):
    """A grid in the xy plane facing +z, and two morph targets: a wave along x (one period across) and a
    bulge towards +z, largest at mid height; their normal deltas tilt the rest normal (0, 0, 1) as the
    displaced surface's normals tilt."""
    positions, normals, wave, bulge, indices = [], [], [], [], []
    for r in range(rows + 1):
        for c in range(columns + 1):
            x, y = width * (c / columns - 0.5), height * (r / rows - 0.5)
            positions.append([x, y, 0.0])
            normals.append([0.0, 0.0, 1.0])
            k = 2 * math.pi / width
            wave.append(([0.0, 0.0, 0.35 * math.sin(k * x)], [-0.35 * k * math.cos(k * x), 0.0, 0.0]))
            h = height / 2
            bulge.append(([0.0, 0.0, 0.6 * (1 - (y / h) ** 2)], [0.0, 1.2 * y / (h * h), 0.0]))
    for r in range(rows):
        for c in range(columns):
            a = r * (columns + 1) + c
            b, d = a + 1, a + columns + 1
            indices += [a, b, d + 1, a, d + 1, d]
    split = lambda pairs: ([p for p, _ in pairs], [n for _, n in pairs])
    return positions, normals, indices, [split(wave), split(bulge)]


def morphing():
    g = Builder()
    chrome, grey, red = materials(g, "chrome", "floor", "red")
    yellow = g.material("cloth", (0.9, 0.75, 0.1), 0.0, 0.7)
    positions, normals, indices, targets = cloth(4.0, 2.4, 24, 16)
    sheet = g.mesh("cloth", positions, normals, indices, yellow, targets=targets)
    cube_positions, cube_normals, cube_indices = box((0.4, 0.4, 0.4))
    rise = [[0.0, 0.6 if p[1] > 0 else 0.0, 0.0] for p in cube_positions]
    cube = g.mesh("red box", cube_positions, cube_normals, cube_indices, red,
                  targets=[(rise, [[0.0, 0.0, 0.0]] * len(rise))], weights=[0.0])
    mirror = g.node(name="mirror", mesh=g.mesh("ball", *sphere(1.0, 24, 48), chrome), translation=[0, 1.2, 0])
    # The cloth stands left of the sphere facing it (+z turned to +x), the box front right: both reflected.
    flag = g.node(name="cloth", mesh=sheet, translation=[-2.2, 1.4, 0.6], weights=[0.2, 0.0],
                  rotation=[0, math.sin(math.pi / 4), 0, math.cos(math.pi / 4)])
    red_box = g.node(name="red box", mesh=cube, translation=[1.3, 0.4, 1.5])
    ground = g.node(name="floor", mesh=g.mesh("floor", *quad(5.0), grey))
    camera = camera_looking_down(g, 0.8, [0.8, 2.6, 6.5], 12.0)
    g.animation("wave", [
        (flag, "weights", "LINEAR", [0, 1, 2], [0, 0, 1, 0.5, 0, 1]),
        (red_box, "weights", "CUBICSPLINE", [0, 2], [0, 0, 0, 0, 1, 0]),
    ])
    g.doc["scenes"] = [{"nodes": [ground, mirror, flag, red_box, camera]}]
    g.write_glb("morphing.glb")


def arm(g, material, base):
    """A tube 2 m tall (12 sides, 16 rings, radius 0.2) from `base` up, skinned to joints "shoulder" at its
    base and "elbow" 1 m up (its child): vertices below 0.75 m follow the shoulder, above 1.25 m the elbow,
    blended linearly between (JOINTS_0 as bytes, WEIGHTS_0 floats). Returns its mesh, the two joint
    nodes and the skin."""
    sides, rings, radius = 12, 16, 0.2
    positions, normals, joints, weights, indices = [], [], [], [], []
    for r in range(rings + 1):
        y = 2.0 * r / rings
        elbow = min(max((y - 0.75) / 0.5, 0.0), 1.0)
        for k in range(sides):
            a = 2 * math.pi * k / sides
            n = [math.cos(a), 0.0, -math.sin(a)]
            positions.append([base[0] + radius * n[0], y, base[2] + radius * n[2]])
            normals.append(n)
            joints += [0, 1, 0, 0]
            weights += [1.0 - elbow, elbow, 0.0, 0.0]
    for r in range(rings):
        for k in range(sides):
            a, b = r * sides + k, r * sides + (k + 1) % sides
            indices += [a, b, b + sides, a, b + sides, a + sides]
    mesh = g.mesh("arm", positions, normals, indices, material)
    attributes = g.doc["meshes"][mesh]["primitives"][0]["attributes"]
    attributes["JOINTS_0"] = g.accessor(bytes(joints), "VEC4", len(positions), 5121)
    attributes["WEIGHTS_0"] = g.accessor(pack(weights), "VEC4", len(positions), 5126)
    inverse_binds = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -base[0], 0, -base[2], 1,
                     1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -base[0], -1, -base[2], 1]
    elbow = g.node(name="elbow", translation=[0, 1, 0])
    shoulder = g.node(name="shoulder", translation=base, children=[elbow])
    g.doc.setdefault("skins", []).append({"joints": [shoulder, elbow],
                                          "inverseBindMatrices": g.accessor(pack(inverse_binds), "MAT4", 2, 5126)})
    return mesh, shoulder, elbow, len(g.doc["skins"]) - 1


def about(axis, degrees):
    return [c * math.sin(math.radians(degrees) / 2) for c in axis] + [math.cos(math.radians(degrees) / 2)]


def bend(shoulder, elbow):
    """The arm's animation: the shoulder turns 90 degrees about y over 2 s, the elbow bends 0-60-0 about z."""
    return [(shoulder, "rotation", "LINEAR", [0, 2], about([0, 1, 0], 0) + about([0, 1, 0], 90)),
            (elbow, "rotation", "LINEAR", [0, 1, 2], about([0, 0, 1], 0) + about([0, 0, 1], 60) + about([0, 0, 1], 0))]


def skinned():
    g = Builder()
    chrome, grey = materials(g, "chrome", "floor")
    green = g.material("arm", (0.1, 0.7, 0.3), 0.0, 0.6)
    mesh, shoulder, elbow, skin = arm(g, green, [1.3, 0.0, 1.4])  # front right of the sphere: reflected in it
    arm_node = g.node(name="arm", mesh=mesh, skin=skin, translation=[5, 0, 0])
    mirror = g.node(name="mirror", mesh=g.mesh("ball", *sphere(1.0, 24, 48), chrome), translation=[0, 1.2, 0])
    ground = g.node(name="floor", mesh=g.mesh("floor", *quad(5.0), grey))
    camera = camera_looking_down(g, 0.8, [0.8, 2.6, 6.5], 12.0)
    g.animation("bend", bend(shoulder, elbow))
    g.doc["scenes"] = [{"nodes": [ground, mirror, shoulder, arm_node, camera]}]
    g.write_glb("skinned.glb")


def deforming_mirrors():
    g = Builder()
    chrome, grey, red, green, blue = materials(g, "chrome", "floor", "red", "green", "blue")
    positions, normals, indices = sphere(1.0, 24, 48)
    # Squashed: 1.3 times wider, 0.65 times as tall; the normal delta is the squashed ellipsoid's normal's.
    squash = [[0.3 * p[0], -0.35 * p[1], 0.3 * p[2]] for p in positions]
    def squashed_normal(n):
        m = [n[0] / 1.3, n[1] / 0.65, n[2] / 1.3]
        length = math.sqrt(sum(c * c for c in m))
        return [m[i] / length - n[i] for i in range(3)]
    ball = g.mesh("ball", positions, normals, indices, chrome,
                  targets=[(squash, [squashed_normal(n) for n in normals])])
    mesh, shoulder, elbow, skin = arm(g, chrome, [1.4, 0.0, 0.4])
    nodes = [
        g.node(name="floor", mesh=g.mesh("floor", *quad(5.0), grey)),
        g.node(name="mirror", mesh=ball, translation=[-0.9, 1.1, 0]),
        shoulder,
        g.node(name="chrome arm", mesh=mesh, skin=skin),
        g.node(name="red box", mesh=g.mesh("red box", *box((0.4, 0.4, 0.4)), red), translation=[0.2, 0.4, 2.0]),
        g.node(name="green box", mesh=g.mesh("green box", *box((0.5, 0.5, 0.5)), green), translation=[2.6, 0.5, -1.2]),
        g.node(name="blue box", mesh=g.mesh("blue box", *box((0.5, 0.5, 0.5)), blue), translation=[-2.8, 0.5, 0.8]),
    ]
    nodes.append(camera_looking_down(g, 0.8, [0.4, 2.6, 6.5], 12.0))
    g.animation("squash and bend", [(nodes[1], "weights", "LINEAR", [0, 1, 2], [0, 1, 0])] + bend(shoulder, elbow))
    g.doc["scenes"] = [{"nodes": nodes}]
    g.write_glb("deforming-mirrors.glb")


def engine():
    g = Builder()
    paint = g.material("engine blue", (0.12, 0.22, 0.42), 0.2, 0.5)
    iron = g.material("cast iron", (0.18, 0.18, 0.19), 0.5, 0.6)
    alu = g.material("aluminium", (0.72, 0.73, 0.75), 0.7, 0.35)
    chrome = g.material("chrome", (0.95, 0.95, 0.95), 1.0, 0.04)
    rubber = g.material("rubber", (0.03, 0.03, 0.03), 0.0, 0.9)
    copper = g.material("copper", (0.72, 0.38, 0.2), 0.8, 0.3)
    red = g.material("ignition red", (0.7, 0.06, 0.04), 0.0, 0.5)
    white = g.material("porcelain", (0.9, 0.9, 0.86), 0.0, 0.2)
    m = {}
    m["block"] = g.mesh("block", *box((0.9, 0.45, 0.45)), paint)
    m["crankcase"] = g.mesh("crankcase", *box((0.95, 0.3, 0.5)), paint)
    m["oil pan"] = g.mesh("oil pan", *box((0.85, 0.15, 0.42)), iron)
    m["barrel"] = g.mesh("barrel", *cylinder(0.3, 0.7, 48), paint)
    m["head"] = g.mesh("head", *box((0.36, 0.12, 0.36)), alu)
    m["valve cover"] = g.mesh("valve cover", *box((0.3, 0.08, 0.3)), chrome)
    m["piston"] = g.mesh("piston", *cylinder(0.2, 0.25, 32), alu)
    m["piston pin"] = g.mesh("piston pin", *cylinder(0.05, 0.36, 16, axis=2), iron)
    m["rod"] = g.mesh("rod", *box((0.05, 0.35, 0.04)), iron)
    m["crank throw"] = g.mesh("crank throw", *box((0.06, 0.18, 0.12)), iron)
    m["crankshaft"] = g.mesh("crankshaft", *cylinder(0.07, 2.4, 32, axis=0), iron)
    m["flywheel"] = g.mesh("flywheel", *cylinder(0.55, 0.12, 96, axis=0), chrome)
    m["ring gear"] = g.mesh("ring gear", *torus(0.56, 0.04, 96, 12), iron)
    m["pulley"] = g.mesh("pulley", *cylinder(0.22, 0.1, 48, axis=0), alu)
    m["belt"] = g.mesh("belt", *torus(0.24, 0.03, 64, 10), rubber)
    m["alternator"] = g.mesh("alternator", *cylinder(0.16, 0.3, 32, axis=0), alu)
    m["runner"] = g.mesh("intake runner", *cylinder(0.06, 0.5, 24), alu)
    m["plenum"] = g.mesh("plenum", *box((0.7, 0.1, 0.12)), alu)
    m["header"] = g.mesh("exhaust header", *cylinder(0.07, 0.6, 32, axis=2), chrome)
    m["collector"] = g.mesh("exhaust collector", *cylinder(0.1, 1.1, 32, axis=0), iron)
    m["spark plug"] = g.mesh("spark plug", *cylinder(0.03, 0.16, 16), white)
    m["plug wire"] = g.mesh("plug wire", *torus(0.12, 0.015, 32, 8), red)
    m["bolt"] = g.mesh("bolt head", *cylinder(0.035, 0.03, 6), iron)
    m["stud"] = g.mesh("stud", *cylinder(0.015, 0.12, 8), copper)
    m["bracket"] = g.mesh("mount bracket", *box((0.1, 0.2, 0.25)), iron)
    m["mount"] = g.mesh("rubber mount", *cylinder(0.09, 0.12, 24), rubber)
    m["oil cap"] = g.mesh("oil cap", *sphere(0.09, 16, 32), chrome)
    m["dipstick"] = g.mesh("dipstick", *cylinder(0.015, 0.6, 8), copper)
    m["base"] = g.mesh("base plate", *box((1.6, 0.05, 0.9)), iron)
    assert len(g.doc["meshes"]) == 29
    N = lambda **fields: g.node(**fields)
    bolts = lambda points: [N(name="bolt", mesh=m["bolt"], translation=p) for p in points]
    # Each cylinder: barrel > head > valve cover, bolts, plug > wire; piston > pin, rod; header; runner.
    def cylinder_bank(side, x):
        cover = N(name=side + " valve cover", mesh=m["valve cover"], translation=[0, 0.18, 0])
        plug = N(name=side + " spark plug", mesh=m["spark plug"], translation=[0.2, 0.2, 0],
                 children=[N(name=side + " plug wire", mesh=m["plug wire"], translation=[0, 0.08, 0],
                             rotation=[0.7071068, 0, 0, 0.7071068])])
        head = N(name=side + " head", mesh=m["head"], translation=[0, 0.47, 0],
                 children=[cover, plug] + bolts([[sx * 0.28, 0.13, sz * 0.28] for sx in (-1, 1) for sz in (-1, 1)]))
        pin = N(name=side + " piston pin", mesh=m["piston pin"])
        rod = N(name=side + " rod", mesh=m["rod"], translation=[0, -0.35, 0])
        piston = N(name=side + " piston", mesh=m["piston"], translation=[0, 0.1, 0], children=[pin, rod])
        header = N(name=side + " exhaust header", mesh=m["header"], translation=[0, 0.2, 0.55])
        runner = N(name=side + " intake runner", mesh=m["runner"], translation=[0, 0.35, -0.42], rotation=[0.2588190, 0, 0, 0.9659258])
        return N(name=side + " cylinder", mesh=m["barrel"], translation=[x, 0.8, 0], children=[head, piston, header, runner])
    left, right = cylinder_bank("left", -0.45), cylinder_bank("right", 0.45)
    throws = [N(name=name, mesh=m["crank throw"], translation=[x, 0.1, 0]) for name, x in (("left throw", -0.45), ("right throw", 0.45))]
    flywheel = N(name="flywheel", mesh=m["flywheel"], translation=[1.25, 0, 0],
                 children=[N(name="ring gear", mesh=m["ring gear"], rotation=[0, 0, 0.7071068, 0.7071068])])
    pulley = N(name="pulley", mesh=m["pulley"], translation=[-1.25, 0, 0],
               children=[N(name="belt", mesh=m["belt"], rotation=[0, 0, 0.7071068, 0.7071068], translation=[0, 0.25, 0])])
    crank = N(name="crankshaft", mesh=m["crankshaft"], translation=[0, -0.2, 0], children=throws + [flywheel, pulley])
    alternator = N(name="alternator", mesh=m["alternator"], translation=[-1.1, 0.55, 0.35],
                   children=bolts([[0.16, 0, 0.12], [0.16, 0, -0.12]]))
    plenum = N(name="intake plenum", mesh=m["plenum"], translation=[0, 1.35, -0.55],
               children=[N(name="stud", mesh=m["stud"], translation=[x, 0.12, 0]) for x in (-0.5, 0, 0.5)])
    collector = N(name="exhaust collector", mesh=m["collector"], translation=[0, 1.0, 0.75])
    block = N(name="block", mesh=m["block"], translation=[0, 0.3, 0],
              children=[left, right, alternator, plenum, collector,
                        N(name="oil cap", mesh=m["oil cap"], translation=[0.6, 0.5, -0.2]),
                        N(name="dipstick", mesh=m["dipstick"], translation=[-0.7, 0.4, 0.35])]
              + bolts([[x, 0.46, z] for x in (-0.8, -0.1, 0.1, 0.8) for z in (-0.38, 0.38)]))
    crankcase = N(name="crankcase", mesh=m["crankcase"], translation=[0, -0.45, 0],
                  children=[crank, N(name="oil pan", mesh=m["oil pan"], translation=[0, -0.42, 0])]
                  + bolts([[x, -0.3, z] for x in (-0.85, 0, 0.85) for z in (-0.5, 0.5)]))
    mounts = [N(name="mount " + str(i), mesh=m["bracket"], translation=[sx * 1.05, -0.45, sz * 0.25],
                children=[N(name="rubber mount " + str(i), mesh=m["mount"], translation=[0, -0.25, 0])])
              for i, (sx, sz) in enumerate(((-1, -1), (-1, 1), (1, -1), (1, 1)))]
    # The engine stands on its base plate; a matrix places it (scale 1, lifted 1.2).
    engine_node = N(name="engine", matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1.2, 0, 1], children=[block, crankcase] + mounts)
    base = N(name="base plate", mesh=m["base"], translation=[0, 0.05, 0])
    root = N(name="2-cylinder engine", children=[base, engine_node])
    while len(g.doc["nodes"]) < 80:  # bolts along the base plate's rim up to the 82 nodes of the public model
        g.doc["nodes"][base]["children"] = g.doc["nodes"][base].get("children", []) + [N(name="bolt", mesh=m["bolt"],
            translation=[-1.5 + 0.15 * len(g.doc["nodes"][base].get("children", [])), 0.065, 0.8])]
    g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0},
                                                              {"type": "point", "intensity": 40.0, "color": [1.0, 0.9, 0.8]}]}}
    sun = N(name="sun", rotation=[-0.4, 0.3, 0, 0.866], extensions={"KHR_lights_punctual": {"light": 0}})
    lamp = N(name="lamp", translation=[2.5, 4.0, 3.0], extensions={"KHR_lights_punctual": {"light": 1}})
    g.doc["scenes"] = [{"name": "engine", "nodes": [root, sun, lamp]}]
    assert len(g.doc["nodes"]) == 82, len(g.doc["nodes"])
    g.write_glb("engine.glb")


if __name__ == "__main__":
    node_tree()
    chrome_sphere()
    textured_box()
    animated()
    open_chrome()
    morphing()
    skinned()
    deforming_mirrors()
    engine()
