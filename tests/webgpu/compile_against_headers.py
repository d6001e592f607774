#!/usr/bin/env python3
# Keeps the WebGPU code compiling against both webgpu_cpp.h headers: volgraph's own
# (graph/rhi/webgpu/include) and Dawn's generated one (../shared/webgpu/dawn-headers).
# The build compiles against one of them; this compiles against the other, syntax only
# (clang -fsyntax-only, the build's own flags from compile_commands.json):
#   tus      every translation unit whose include path has the build's WebGPU headers
#            (the backend, tools/webgpu_backend.cpp, the WebGPU and GPU tests);
#   refused  each snippet in tests/webgpu/refused/: without REFUSED it compiles against
#            both headers, with -DREFUSED it fails against both, so ours refuses what
#            Dawn's refuses.
#   compile_against_headers.py tus|refused COMPILE_COMMANDS BUILD_HEADERS OTHER_HEADERS [SNIPPET_DIR]
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def load_commands(path):
    with open(path) as f:
        return json.load(f)


def arguments(entry):
    return entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])


def uses_headers(args, include_dir):
    return any(a in ("-I", "-isystem") and args[i + 1] == include_dir for i, a in enumerate(args[:-1])) or \
        ("-I" + include_dir) in args


INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def include_dirs(args):
    return [args[i + 1] for i, a in enumerate(args[:-1]) if a == "-I"] + [a[2:] for a in args if a.startswith("-I") and len(a) > 2]


def reaches_webgpu(path, dirs, seen):
    """Whether a file includes <webgpu/...>, directly or through the project's headers."""
    if path in seen:
        return False
    seen.add(path)
    try:
        with open(path) as f:
            text = f.read()
    except OSError:
        return False
    for name in INCLUDE.findall(text):
        if name.startswith("webgpu/"):
            return True
        for d in [os.path.dirname(path)] + dirs:
            candidate = os.path.normpath(os.path.join(d, name))
            if os.path.isfile(candidate):
                if reaches_webgpu(candidate, dirs, seen):
                    return True
                break
    return False


def syntax_only(args, build_headers, other_headers):
    """The build's command with the other headers on the include path, checking syntax only."""
    out, skip = [], False
    for i, a in enumerate(args):
        if skip:
            skip = False
            continue
        if a == "-o":
            skip = True
            continue
        if a == "-c":
            continue
        if a == build_headers and i > 0 and args[i - 1] in ("-I", "-isystem"):
            out.append(other_headers)
            continue
        out.append("-I" + other_headers if a == "-I" + build_headers else a)
    return out + ["-fsyntax-only"]


def run(args, cwd):
    result = subprocess.run(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return result.returncode, result.stdout


def jobs():
    return max(1, min(4, os.cpu_count() or 1))


def check_tus(entries, build_headers, other_headers):
    # Every unit on whose include path the headers are, that includes them (directly or
    # through the project's headers): the others cannot tell the two headers apart.
    chosen = [e for e in entries if uses_headers(arguments(e), build_headers) and
              reaches_webgpu(os.path.join(e["directory"], e["file"]), include_dirs(arguments(e)), set())]
    files = sorted({e["file"] for e in chosen})
    chosen = [next(e for e in chosen if e["file"] == f) for f in files]  # a unit built twice once
    if not chosen:
        print(f"no translation unit includes {build_headers}: nothing checked", file=sys.stderr)
        return 1
    with concurrent.futures.ThreadPoolExecutor(jobs()) as pool:
        results = list(pool.map(
            lambda e: (e["file"], *run(syntax_only(arguments(e), build_headers, other_headers), e["directory"])),
            chosen))
    failed = [(f, out) for f, code, out in results if code != 0]
    for f, out in failed:
        print(f"{f} does not compile against {other_headers}:\n{out}")
    print(f"{len(chosen) - len(failed)} of {len(chosen)} translation units compile against {other_headers}")
    return 1 if failed else 0


def snippet_command(template, build_headers, snippet, include_dir, refused):
    """The flags of a WebGPU translation unit, for a snippet against one of the headers."""
    flags = [a for a in syntax_only(arguments(template), build_headers, include_dir) if a != template["file"]]
    return flags + (["-DREFUSED"] if refused else []) + [snippet]


def check_refused(entries, build_headers, other_headers, snippet_dir):
    template = next((e for e in entries if uses_headers(arguments(e), build_headers)), None)
    if template is None:
        print(f"no translation unit includes {build_headers}", file=sys.stderr)
        return 1
    snippets = sorted(os.path.join(os.path.abspath(snippet_dir), f) for f in os.listdir(snippet_dir) if f.endswith(".cpp"))
    with tempfile.TemporaryDirectory() as tmp:
        # The accepted forms of every snippet in one translation unit per header (fast);
        # each refused form on its own, so that one failure cannot hide another.
        together = os.path.join(tmp, "accepted.cpp")
        with open(together, "w") as f:
            f.writelines(f'#include "{s}"\n' for s in snippets)
        cases = [(together, h, False) for h in (build_headers, other_headers)] + \
                [(s, h, True) for s in snippets for h in (build_headers, other_headers)]
        with concurrent.futures.ThreadPoolExecutor(jobs()) as pool:
            results = list(pool.map(
                lambda c: (c, *run(snippet_command(template, build_headers, *c), template["directory"])), cases))
    failures = 0
    for (snippet, headers, refused), code, out in results:
        name = os.path.basename(snippet)
        if refused and code == 0:
            print(f"{name}: {headers} accepts what it must refuse (-DREFUSED)")
            failures += 1
        elif not refused and code != 0:
            print(f"the accepted forms (tests/webgpu/refused/*.cpp without REFUSED): {headers} refuses them:\n{out}")
            failures += 1
    print(f"{len(snippets)} snippets, {len(cases)} compiles: {len(cases) - failures} as expected")
    return 1 if failures else 0


def main():
    if len(sys.argv) < 5 or sys.argv[1] not in ("tus", "refused"):
        print("usage: compile_against_headers.py tus|refused COMPILE_COMMANDS BUILD_HEADERS OTHER_HEADERS "
              "[SNIPPET_DIR]", file=sys.stderr)
        return 2
    mode, commands, build_headers, other_headers = sys.argv[1:5]
    entries = load_commands(commands)
    if mode == "tus":
        return check_tus(entries, build_headers, other_headers)
    return check_refused(entries, build_headers, other_headers, sys.argv[5])


if __name__ == "__main__":
    sys.exit(main())
