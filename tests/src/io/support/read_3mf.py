"""An independent 3MF reader for the tests (Python's standard library only: zipfile, xml.etree).

Reads a 3MF package the way a slicer finds its model: the root relationship of type 3dmodel in
_rels/.rels names the model part; [Content_Types].xml must give the .model and .rels types. Prints
JSON: the unit, the vertices, the triangles (v1 v2 v3 and their pid p1 p2 p3, None when absent),
every colour group (id -> #RRGGBB list) and the object's default pid/pindex.
"""
import json
import sys
import xml.etree.ElementTree as ET
import zipfile

CORE = "{http://schemas.microsoft.com/3dmanufacturing/core/2015/02}"
MAT = "{http://schemas.microsoft.com/3dmanufacturing/material/2015/02}"
RELS = "{http://schemas.openxmlformats.org/package/2006/relationships}"
TYPES = "{http://schemas.openxmlformats.org/package/2006/content-types}"
MODEL_REL = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"


def opt_int(value):
    return None if value is None else int(value)


def main(path):
    with zipfile.ZipFile(path) as z:
        types = ET.fromstring(z.read("[Content_Types].xml"))
        defaults = {d.get("Extension"): d.get("ContentType") for d in types.iter(TYPES + "Default")}
        rels = ET.fromstring(z.read("_rels/.rels"))
        targets = [r.get("Target") for r in rels.iter(RELS + "Relationship") if r.get("Type") == MODEL_REL]
        model = ET.fromstring(z.read(targets[0].lstrip("/")))
    groups = {
        g.get("id"): [c.get("color") for c in g.iter(MAT + "color")] for g in model.iter(MAT + "colorgroup")
    }
    objects = list(model.iter(CORE + "object"))
    obj = objects[0]
    vertices = [[float(v.get(a)) for a in "xyz"] for v in obj.iter(CORE + "vertex")]
    triangles = [
        [int(t.get("v1")), int(t.get("v2")), int(t.get("v3")), opt_int(t.get("pid")), opt_int(t.get("p1")),
         opt_int(t.get("p2")), opt_int(t.get("p3"))]
        for t in obj.iter(CORE + "triangle")
    ]
    items = [i.get("objectid") for i in model.iter(CORE + "item")]
    print(json.dumps({
        "contentTypes": defaults,
        "modelTargets": targets,
        "unit": model.get("unit"),
        "objects": len(objects),
        "object": {"id": obj.get("id"), "pid": obj.get("pid"), "pindex": obj.get("pindex")},
        "buildItems": items,
        "colorGroups": groups,
        "vertices": vertices,
        "triangles": triangles,
    }))


if __name__ == "__main__":
    main(sys.argv[1])
