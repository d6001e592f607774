#!/usr/bin/env python3
# Generates volgraph's webgpu/webgpu.h and webgpu/webgpu_cpp.h from Dawn's dawn.json for
# the subset in subset.py. Run after changing the subset (or the dawn.json revision):
#   tools/webgpu/gen_webgpu_headers.py [DAWN_JSON] [OUT_DIR]
# defaults: ../shared/webgpu/dawn.json, graph/rhi/webgpu/include/webgpu. The outputs are
# committed; a test checks the committed headers against dawn.json's layout rules.
import os
import sys

import api_model
import c_header
import cpp_header
import subset

REVISION = ("Written from dawn.json of google/dawn df73f162050983d95e38f2404ef4e4e3c86d6be0 "
            "(2025-06-24), the API of libwebgpu_wrapper.so in npm bun-webgpu-linux-x64@0.1.7.")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    dawn_json = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "..", "shared", "webgpu", "dawn.json")
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "graph", "rhi", "webgpu", "include", "webgpu")
    api = api_model.Api(dawn_json)
    api.select(subset.OBJECTS, subset.FUNCTIONS, subset.EXTRA_STRUCTURES, subset.EXTRA_ENUMS)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "webgpu.h"), "w") as f:
        f.write(c_header.write(api, REVISION))
    with open(os.path.join(out_dir, "webgpu_cpp.h"), "w") as f:
        f.write(cpp_header.write(api, REVISION))


if __name__ == "__main__":
    main()
