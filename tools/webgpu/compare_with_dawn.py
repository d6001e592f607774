#!/usr/bin/env python3
# Compares the declarations of volgraph's webgpu_cpp.h with Dawn's generated one of the
# same revision: every method of every handle class (name, argument types, defaults,
# const) and every member of every struct (type, constness, name, default) that ours
# declares must be declared the same way in Dawn's. Ours is a subset: what Dawn has
# beyond it is not checked. Known, deliberate differences are listed in ALLOWED.
#   compare_with_dawn.py OUR_WEBGPU_CPP_H DAWN_WEBGPU_CPP_H
# (Dawn's is dawn-headers/include/dawn/webgpu_cpp.h; its webgpu/webgpu_cpp.h forwards.)
import re
import sys

# Written by hand on both sides (cpp_support.py), compared by reading and by the
# snippets of tests/webgpu/refused/.
HAND_WRITTEN = {"StringView", "ConvertibleStatus", "Bool", "OptionalBool", "ObjectBase", "DeviceDescriptorLayout"}

ALLOWED = {
    # Dawn initialises the C callback infos with the _INIT macros of its webgpu.h, which
    # ours does not declare; the values are the same (all zero).
    ("DeviceDescriptor", "WGPUDeviceLostCallbackInfo deviceLostCallbackInfo = {};"),
    ("DeviceDescriptor", "WGPUUncapturedErrorCallbackInfo uncapturedErrorCallbackInfo = {};"),
    # Ours checks the protected members' layout from a friend.
    ("DeviceDescriptor", "private:"),
    ("DeviceDescriptor", "friend struct DeviceDescriptorLayout;"),
}


def norm(s):
    s = re.sub(r"\s+", " ", s).strip()
    s = re.sub(r"\s*([*&,()<>])\s*", r"\1", s)
    s = s.replace(",", ", ")
    s = s.replace("const char*", "char const*")
    s = re.sub(r"^inline ", "", s)
    # Dawn's callback methods also take the deprecated const char* message form.
    s = re.sub(r"typename CbChar ?=.*?, typename ?=", "typename =", s)
    s = re.sub(r" ?\|\| ?std::is_convertible_v<[FL], CbChar\*?>", "", s)
    return s


def blocks(text):
    out = {}
    for m in re.finditer(r"^(?:class|struct) (\w+)(?: : [^{;]*?)?\s*\{\n(.*?)^\};", text, re.M | re.S):
        out.setdefault(m.group(1), m.group(2))
    return out


def declarations(body):
    out, current = [], ""
    for line in body.split("\n"):
        stripped = line.strip()
        if not stripped or stripped.startswith("//"):
            continue
        current += " " + stripped
        if stripped.endswith(";") or stripped.endswith(":"):
            out.append(norm(current))
            current = ""
    return out


def main():
    if len(sys.argv) != 3:
        print("usage: compare_with_dawn.py OUR_WEBGPU_CPP_H DAWN_WEBGPU_CPP_H", file=sys.stderr)
        return 2
    ours, dawn = (blocks(open(p).read()) for p in sys.argv[1:3])
    problems, compared = [], 0
    for name, body in ours.items():
        if name in HAND_WRITTEN:
            continue
        if name not in dawn:
            problems.append(f"{name}: not declared in Dawn's header")
            continue
        theirs = set(declarations(dawn[name]))
        for d in declarations(body):
            compared += 1
            if d not in theirs and (name, d) not in ALLOWED:
                problems.append(f"{name}: `{d}` is not in Dawn's {name}")
    for p in problems:
        print(p)
    print(f"{len(ours) - len(HAND_WRITTEN & set(ours))} classes and structs, {compared} declarations compared; "
          f"{len(problems)} differ from Dawn's")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
