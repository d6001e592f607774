# The handle classes of webgpu_cpp.h: their method declarations and inline definitions,
# Dawn's templated callback overloads for methods that take a callback info, and the
# callback type aliases those use.
from api_model import CamelCase, camelCase
from c_header import c_type
import cpp_header as ch

SPECIAL_CALLBACKS = ("device lost callback", "uncaptured error callback")


def cb_arg_cpp(api, arg):
    return ch.cpp_annotated(api, arg)


def callback_aliases(api):
    lines = []
    for cb in api.of_category("callback function"):
        if cb in SPECIAL_CALLBACKS:
            continue
        args = ", ".join(cb_arg_cpp(api, a) for a in api.json[cb].get("args", []))
        lines.append(f"template <typename... T>\nusing {CamelCase(cb)} = typename detail::CallbackTypeBase<"
                     f"std::tuple<{args}>, T...>::Callback;")
    for cb, second in (("DeviceLostCallback", "DeviceLostReason"), ("UncapturedErrorCallback", "ErrorType")):
        lines.append(f"template <typename... T>\nusing {cb} = typename detail::CallbackTypeBase<"
                     f"std::tuple<const Device&, {second}, StringView>, T...>::Callback;")
    return "\n".join(lines)


def arg_decl(api, arg, with_default):
    cat = api.types[arg["type"]]
    name = camelCase(arg["name"])
    if cat == "object" and arg.get("annotation", "value") == "value":
        decl = f"{ch.cpp_type(api, arg['type'])} const& {name}"
    else:
        decl = f"{ch.cpp_annotated(api, arg)} {name}"
    return decl + (arg_default(api, arg) if with_default else "")


def arg_default(api, arg):
    """Dawn's default for a method argument (pointers and values with a dawn.json default)."""
    if arg.get("no_default"):
        return ""
    cat = api.types[arg["type"]]
    default = arg.get("default")
    if arg.get("annotation", "value") != "value":
        return " = nullptr" if arg.get("optional") or default == "nullptr" else ""
    if cat == "object":
        return " = nullptr" if arg.get("optional") else ""
    if cat == "enum" and default is not None:
        return f" = {ch.cpp_type(api, arg['type'])}::{ch.cpp_enum_name(default)}"
    if cat == "native" and default is not None:
        if str(default) in api.constants():
            return f" = k{CamelCase(str(default))}"
        return f" = {default}"
    return ""


def c_arg(api, arg):
    """The C value of a C++ argument."""
    name = camelCase(arg["name"])
    cat = api.types[arg["type"]]
    if arg.get("annotation", "value") != "value":
        if cat == "native":
            return name
        ctype = c_type(api, arg["type"])
        const = " const" if arg["annotation"] == "const*" else ""
        return f"reinterpret_cast<{ctype}{const} *>({name})"
    if cat == "object":
        return f"{name}.Get()"
    if cat in ("enum", "bitmask"):
        return f"static_cast<{c_type(api, arg['type'])}>({name})"
    if cat == "structure":
        return f"*reinterpret_cast<{c_type(api, arg['type'])} const*>(&{name})"
    return name


def return_type(api, method):
    ret = method.get("returns")
    if ret is None or ret == "void":
        return "void"
    if ret == "status":
        return "ConvertibleStatus"
    return ch.cpp_type(api, ret)


def convert_return(api, method, expr):
    ret = method.get("returns")
    cat = api.types.get(ret)
    if ret == "status":
        return f"ConvertibleStatus(static_cast<Status>({expr}))"
    if cat == "object":
        return f"{ch.cpp_type(api, ret)}::Acquire({expr})"
    if cat in ("enum", "bitmask"):
        return f"static_cast<{ch.cpp_type(api, ret)}>({expr})"
    if ret == "future":
        return f"Future{{({expr}).id}}"
    return expr


def c_call(api, obj, method, args):
    return f"wgpu{CamelCase(obj)}{CamelCase(method['name'])}({', '.join(['Get()'] + args)})"


def is_callback_method(api, method):
    args = method.get("args", [])
    return bool(args) and api.types[args[-1]["type"]] == "callback info"


def callback_parts(api, method):
    info = method["args"][-1]["type"]
    has_mode = any(m["name"] == "mode" for m in api.members(info))
    callback = next(m["type"] for m in api.members(info) if m["name"] == "callback")
    return info, has_mode, callback


def lead_args(api, method, with_default=False):
    return [arg_decl(api, a, with_default) for a in method["args"][:-1]]


def simple_decl(api, obj, method):
    args = ", ".join(arg_decl(api, a, True) for a in method.get("args", []))
    return f"    inline {return_type(api, method)} {CamelCase(method['name'])}({args}) const;"


def callback_decls(api, obj, method):
    info, has_mode, callback = callback_parts(api, method)
    lead = lead_args(api, method) + (["CallbackMode callbackMode"] if has_mode else [])
    name, ret, cb = CamelCase(method["name"]), return_type(api, method), CamelCase(callback)
    return (f"    template <typename F, typename T, typename Cb = {cb}<T>,\n"
            f"              typename = std::enable_if_t<std::is_convertible_v<F, Cb*>>>\n"
            f"    {ret} {name}({', '.join(lead + ['F callback', 'T userdata'])}) const;\n"
            f"    template <typename L, typename Cb = {cb}<>,\n"
            f"              typename = std::enable_if_t<std::is_convertible_v<L, Cb>>>\n"
            f"    {ret} {name}({', '.join(lead + ['L callback'])}) const;")


def class_decl(api, obj):
    cpp, ctype = ch.cpp_type(api, obj), c_type(api, obj)
    lines = [f"class {cpp} : public ObjectBase<{cpp}, {ctype}> {{", "  public:",
             "    using ObjectBase::ObjectBase;", "    using ObjectBase::operator=;", ""]
    for m in api.methods.get(obj, []):
        lines.append(callback_decls(api, obj, m) if is_callback_method(api, m) else simple_decl(api, obj, m))
    if obj == "instance":
        lines.append("    inline WaitStatus WaitAny(Future f, uint64_t timeout) const;")
    lines += ["", "  private:", f"    friend ObjectBase<{cpp}, {ctype}>;",
              f"    static inline void WGPUAddRef({ctype} handle);",
              f"    static inline void WGPURelease({ctype} handle);", "};", ""]
    return "\n".join(lines)


def c_callback_params(api, callback):
    return [f"{c_type(api, a['type'])} {camelCase(a['name'])}" for a in api.json[callback].get("args", [])]


def cpp_callback_values(api, callback):
    """C callback arguments converted to what the C++ callback takes."""
    values = []
    for a in api.json[callback].get("args", []):
        name, cat = camelCase(a["name"]), api.types[a["type"]]
        if cat == "object":
            values.append(f"{ch.cpp_type(api, a['type'])}::Acquire({name})")
        elif cat in ("enum", "bitmask"):
            values.append(f"static_cast<{ch.cpp_type(api, a['type'])}>({name})")
        elif a["type"] == "string view":
            values.append(f"StringView({name})")
        else:
            values.append(name)
    return values


def callback_impls(api, obj, method):
    info, has_mode, callback = callback_parts(api, method)
    cpp, name, ret = ch.cpp_type(api, obj), CamelCase(method["name"]), return_type(api, method)
    lead = lead_args(api, method) + (["CallbackMode callbackMode"] if has_mode else [])
    params = ", ".join(c_callback_params(api, callback) + ["void* callbackParam", "void* userdataParam"])
    values = cpp_callback_values(api, callback)
    mode = f"    info.mode = static_cast<WGPUCallbackMode>(callbackMode);\n" if has_mode else ""
    call = c_call(api, obj, method, [c_arg(api, a) for a in method["args"][:-1]] + ["info"])
    ret_stmt = f"    return {convert_return(api, method, call)};\n" if ret != "void" else f"    {call};\n"
    info_c = c_type(api, info)
    with_userdata = (
        f"template <typename F, typename T, typename Cb, typename>\n"
        f"{ret} {cpp}::{name}({', '.join(lead + ['F callback', 'T userdata'])}) const {{\n"
        f"    {info_c} info = {{}};\n{mode}"
        f"    info.callback = []({params}) {{\n"
        f"        auto cb = reinterpret_cast<Cb*>(callbackParam);\n"
        f"        (*cb)({', '.join(values + ['static_cast<T>(userdataParam)'])});\n    }};\n"
        f"    info.userdata1 = reinterpret_cast<void*>(+callback);\n"
        f"    info.userdata2 = reinterpret_cast<void*>(userdata);\n{ret_stmt}}}\n")
    callable = (
        f"template <typename L, typename Cb, typename>\n"
        f"{ret} {cpp}::{name}({', '.join(lead + ['L callback'])}) const {{\n"
        f"    using F = {CamelCase(callback)}<void>;\n"
        f"    {info_c} info = {{}};\n{mode}"
        f"    if constexpr (std::is_convertible_v<L, F*>) {{\n"
        f"        info.callback = []({params}) {{\n"
        f"            (void)userdataParam;\n"
        f"            auto cb = reinterpret_cast<F*>(callbackParam);\n"
        f"            (*cb)({', '.join(values)});\n        }};\n"
        f"        info.userdata1 = reinterpret_cast<void*>(+callback);\n"
        f"    }} else {{\n"
        f"        // Called once: the callable is freed after the call.\n"
        f"        info.callback = []({params}) {{\n"
        f"            (void)userdataParam;\n"
        f"            std::unique_ptr<L> lambda(reinterpret_cast<L*>(callbackParam));\n"
        f"            (*lambda)({', '.join(values)});\n        }};\n"
        f"        info.userdata1 = reinterpret_cast<void*>(new L(std::move(callback)));\n"
        f"    }}\n    info.userdata2 = nullptr;\n{ret_stmt}}}\n")
    return with_userdata + callable


def simple_impl(api, obj, method):
    cpp, ret = ch.cpp_type(api, obj), return_type(api, method)
    args = ", ".join(arg_decl(api, a, False) for a in method.get("args", []))
    body = ""
    for a in method.get("args", []):
        if a.get("annotation") == "*" and api.has_free_members(a["type"]):
            body += f"    *{camelCase(a['name'])} = {ch.cpp_type(api, a['type'])}();\n"
    call = c_call(api, obj, method, [c_arg(api, a) for a in method.get("args", [])])
    body += f"    return {convert_return(api, method, call)};\n" if ret != "void" else f"    {call};\n"
    return f"{ret} {cpp}::{CamelCase(method['name'])}({args}) const {{\n{body}}}\n"


def class_impl(api, obj):
    cpp, ctype = ch.cpp_type(api, obj), c_type(api, obj)
    lines = [f"// {cpp}"]
    for m in api.methods.get(obj, []):
        lines.append(callback_impls(api, obj, m) if is_callback_method(api, m) else simple_impl(api, obj, m))
    if obj == "instance":
        lines.append("WaitStatus Instance::WaitAny(Future f, uint64_t timeout) const {\n"
                     "    FutureWaitInfo waitInfo{f};\n"
                     "    return WaitAny(1, &waitInfo, timeout);\n}\n")
    lines.append(f"void {cpp}::WGPUAddRef({ctype} handle) {{\n    if (handle != nullptr) wgpu{CamelCase(obj)}AddRef(handle);\n}}")
    lines.append(f"void {cpp}::WGPURelease({ctype} handle) {{\n    if (handle != nullptr) wgpu{CamelCase(obj)}Release(handle);\n}}\n")
    return "\n".join(lines)


def functions_impl(api):
    lines = []
    for name, fn in api.functions:
        args = ", ".join(arg_decl(api, a, True) for a in fn.get("args", []))
        call = f"wgpu{CamelCase(name)}({', '.join(c_arg(api, a) for a in fn.get('args', []))})"
        ret = fn["returns"]
        lines.append(f"inline {ch.cpp_type(api, ret)} {CamelCase(name)}({args}) {{\n"
                     f"    return {ch.cpp_type(api, ret)}::Acquire({call});\n}}\n")
    return "\n".join(lines)
