# Reads dawn.json into what the header writers need: the subset's types in dependency
# order, with Dawn's naming rules (Name chunks → WGPUCamelCase, camelCase members,
# SNAKE_CASE constants) and its enum value prefixes for extension values.
import json

# Tags of the values, members and methods that Dawn's native webgpu.h contains;
# anything tagged only with others (emscripten-only) is left out, as Dawn does.
ENABLED_TAGS = {"dawn", "native", "upstream", "compat", "deprecated", "art"}


def enabled(entry):
    tags = entry.get("tags")
    return not tags or any(t in ENABLED_TAGS for t in tags)


def chunks(name):
    return name.split(" ")


def camel_chunk(chunk):
    return chunk[0].upper() + chunk[1:]


def CamelCase(name):
    return "".join(camel_chunk(c) for c in chunks(name))


def camelCase(name):
    c = chunks(name)
    return c[0] + "".join(camel_chunk(x) for x in c[1:])


def SNAKE_CASE(name):
    return "_".join(c.upper() for c in chunks(name))


def enum_value(value):
    """A value with Dawn's prefix for extension blocks (0x5xxxx Dawn, 0x2xxxx compat...)."""
    tags = value.get("tags", [])
    prefix = 0
    if "compat" in tags:
        prefix = 0x0002_0000
    if "upstream" not in tags:
        if "dawn" in tags:
            prefix = 0x0005_0000
        elif "emscripten" in tags:
            prefix = 0x0004_0000
    if prefix == 0 and "native" in tags:
        prefix = 0x0001_0000
    return value["value"] + prefix


class Api:
    def __init__(self, path):
        with open(path) as f:
            self.json = json.load(f)
        self.types = {}  # name -> category, for the subset
        self.order = []  # structures in dependency order
        self.methods = {}  # object -> [method json]
        self.functions = []

    def category(self, name):
        return self.json[name]["category"]

    def members(self, name):
        return [m for m in self.json[name].get("members", []) if enabled(m)]

    def enum_values(self, name):
        values = [v for v in self.json[name]["values"] if enabled(v)]
        if name == "s type":  # only the chained structs of the subset
            values = [v for v in values if v["name"] in self.types]
        return values

    def constants(self):
        return {k: v for k, v in self.json.items() if isinstance(v, dict) and v.get("category") == "constant"}

    def select(self, objects, functions, extra_structures, extra_enums):
        for obj, names in objects.items():
            self.add_type(obj)
            by_name = {m["name"]: m for m in self.json[obj].get("methods", []) if enabled(m)}
            missing = [n for n in names if n not in by_name]
            if missing:
                raise SystemExit(f"{obj}: no method {missing} in this dawn.json")
            self.methods[obj] = [by_name[n] for n in names]
            for m in self.methods[obj]:
                self.add_record(m.get("args", []))
                if "returns" in m:
                    self.add_type(m["returns"])
        for fn in functions:
            self.functions.append((fn, self.json[fn]))
            self.add_record(self.json[fn].get("args", []))
            self.add_type(self.json[fn]["returns"])
        for s in extra_structures + extra_enums:
            self.add_type(s)

    def add_record(self, members):
        for m in members:
            if enabled(m):
                self.add_type(m["type"])

    def add_type(self, name):
        if name in self.types:
            return
        cat = self.category(name)
        self.types[name] = cat
        if cat in ("structure", "callback info"):
            self.add_record(self.members(name))
            self.order.append(name)  # after its members: dependency order
        elif cat in ("callback function", "function pointer"):
            self.add_record(self.json[name].get("args", []))
        elif cat == "typedef":
            self.add_type(self.json[name]["type"])
        if cat == "structure" and self.json[name].get("chained"):
            self.add_type("s type")

    def of_category(self, *cats):
        return [n for n, c in self.types.items() if c in cats]

    def is_output(self, name):
        j = self.json[name]
        return j.get("extensible") == "out" or j.get("chained") == "out" or j.get("out", False)

    def has_free_members(self, name):
        if self.category(name) != "structure" or not self.is_output(name):
            return False
        return any(m.get("annotation", "value") != "value" or m["type"] == "string view"
                   for m in self.members(name))
