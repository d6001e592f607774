# The part of the webgpu.h API that volgraph declares: objects with the methods it calls,
# free functions, and structures reached only through chains or out-parameters.
# gen_webgpu_headers.py takes everything these need (argument, member and callback
# types) from dawn.json, so only entry points are listed here.

# object -> methods (dawn.json names). AddRef/Release come with every object.
OBJECTS = {
    "instance": ["process events", "wait any", "request adapter", "create surface"],
    "adapter": ["get limits", "get info", "has feature", "get features", "request device"],
    "device": [
        "create bind group", "create bind group layout", "create buffer",
        "create command encoder", "create compute pipeline", "create pipeline layout",
        "create query set", "create render pipeline", "create sampler",
        "create shader module", "create texture", "destroy", "get limits",
        "get lost future", "has feature", "get features", "get adapter info", "get queue",
        "push error scope", "pop error scope", "set label",
    ],
    "queue": ["submit", "on submitted work done", "write buffer", "write texture", "set label"],
    "buffer": [
        "map async", "get mapped range", "get const mapped range", "set label",
        "get usage", "get size", "get map state", "unmap", "destroy",
    ],
    "texture": [
        "create view", "set label", "get width", "get height", "get depth or array layers",
        "get mip level count", "get sample count", "get dimension", "get format",
        "get usage", "destroy",
    ],
    "texture view": ["set label"],
    "sampler": ["set label"],
    "shader module": ["set label"],
    "bind group layout": ["set label"],
    "bind group": ["set label"],
    "pipeline layout": ["set label"],
    "compute pipeline": ["get bind group layout", "set label"],
    "render pipeline": ["get bind group layout", "set label"],
    "command encoder": [
        "finish", "begin compute pass", "begin render pass", "copy buffer to buffer",
        "copy buffer to texture", "copy texture to buffer", "copy texture to texture",
        "clear buffer", "insert debug marker", "pop debug group", "push debug group",
        "resolve query set", "write timestamp", "set label",
    ],
    "command buffer": ["set label"],
    "compute pass encoder": [
        "insert debug marker", "pop debug group", "push debug group", "set pipeline",
        "set bind group", "dispatch workgroups", "dispatch workgroups indirect", "end",
        "set label",
    ],
    "render pass encoder": [
        "set pipeline", "set bind group", "draw", "draw indexed", "draw indirect",
        "draw indexed indirect", "insert debug marker", "pop debug group",
        "push debug group", "set stencil reference", "set blend constant", "set viewport",
        "set scissor rect", "set vertex buffer", "set index buffer", "end", "set label",
    ],
    "query set": ["set label", "get type", "get count", "destroy"],
    # The viewer's window (viewer/webgpu_presenter.cpp).
    "surface": ["configure", "get capabilities", "get current texture", "present", "unconfigure", "set label"],
}

FUNCTIONS = ["create instance"]

# Structures no method names: chained extensions the backend uses.
EXTRA_STRUCTURES = ["shader source SPIRV", "dawn toggles descriptor", "surface source xlib window"]

# Enums (or values) that no listed method or structure reaches but callers compare with.
EXTRA_ENUMS = ["s type"]
