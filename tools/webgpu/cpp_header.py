# Writes webgpu_cpp.h: a C++ API in the shape and names of Dawn's generated webgpu_cpp.h
# (namespace wgpu, reference-counted handle classes, enum classes, descriptor structs
# with dawn.json's defaults that are layout-compatible with the C structs) over the
# declarations c_header.py writes. The fixed parts live in cpp_support.py.
from api_model import CamelCase, camelCase, enum_value
import cpp_methods
import cpp_support
from c_header import c_type

NATIVE_CPP = {"bool": "Bool"}


def cpp_enum_name(name):
    n = CamelCase(name)
    return "e" + n if n[0].isdigit() else n


def cpp_type(api, name):
    cat = api.types.get(name) or api.category(name)
    if cat == "native":
        return NATIVE_CPP.get(name, name)
    return CamelCase(name)


def cpp_annotated(api, member):
    annotation = member.get("annotation", "value")
    typ = cpp_type(api, member["type"])
    return {"value": typ, "const*": typ + " const *", "*": typ + " *", "const*const*": typ + " const * const *"}[annotation]


# Dawn's C++ header gives these BindGroupLayoutEntry members "binding not used" layouts,
# so that an entry sets only the kind it binds.
BGL_ENTRY_DEFAULTS = {
    "buffer": "{ nullptr, BufferBindingType::BindingNotUsed, false, 0 }",
    "sampler": "{ nullptr, SamplerBindingType::BindingNotUsed }",
    "texture": "{ nullptr, TextureSampleType::BindingNotUsed, TextureViewDimension::e2D, false }",
    "storage texture": "{ nullptr, StorageTextureAccess::BindingNotUsed, TextureFormat::Undefined, TextureViewDimension::e2D }",
}


def member_default(api, struct, member, force):
    """Dawn's default initialiser for a struct member (" = ..." or "")."""
    if struct == "bind group layout entry" and member["name"] in BGL_ENTRY_DEFAULTS:
        return " = " + BGL_ENTRY_DEFAULTS[member["name"]]
    cat = api.types[member["type"]]
    default = member.get("default")
    annotation = member.get("annotation", "value")
    if annotation != "value" or cat == "object":
        return " = nullptr"
    if cat == "enum":
        values = [v["name"] for v in api.enum_values(member["type"])]
        if "undefined" in values:
            return f" = {cpp_type(api, member['type'])}::Undefined"
        if default is not None:
            return f" = {cpp_type(api, member['type'])}::{cpp_enum_name(default)}"
        return " = {}"
    if cat == "bitmask":
        return f" = {cpp_type(api, member['type'])}::{cpp_enum_name(default or 'none')}"
    if cat == "native" and default is not None:
        if str(default) in api.constants():
            return f" = k{CamelCase(str(default))}"
        return f" = {default}"
    if cat == "structure":
        return " = {}"
    return " = {}" if force else ""


def struct_members(api, name, force):
    lines = []
    chained = api.json[name].get("chained")
    # The implementation fills and frees these: callers read them only (as in Dawn's header).
    const = " const" if api.has_free_members(name) else ""
    for i, m in enumerate(api.members(name)):
        decl = f"{cpp_annotated(api, m)}{const} {camelCase(m['name'])}{member_default(api, name, m, force)};"
        if chained and i == 0:
            base = "ChainedStructOut" if chained == "out" else "ChainedStruct"
            align = f"detail::ConstexprMax(alignof({base}), alignof({cpp_annotated(api, m)}))"
            lines.append(f"    static constexpr size_t kFirstMemberAlignment = {align};")
            decl = "alignas(kFirstMemberAlignment) " + decl
        lines.append("    " + decl)
    return lines


def struct_decl(api, name):
    cpp = cpp_type(api, name)
    j = api.json[name]
    free = api.has_free_members(name)
    out = "Out" if api.is_output(name) else ""
    lines = []
    if j.get("chained"):
        lines += [f"struct {cpp} : ChainedStruct{out} {{", f"    inline {cpp}();", "    struct Init;",
                  f"    inline {cpp}(Init&& init);"]
    else:
        lines.append(f"struct {cpp} {{")
    if free:
        lines += [f"    inline {cpp}();", f"    inline ~{cpp}();", f"    {cpp}(const {cpp}&) = delete;",
                  f"    {cpp}& operator=(const {cpp}&) = delete;", f"    inline {cpp}({cpp}&&);",
                  f"    inline {cpp}& operator=({cpp}&&);"]
    lines.append(f"    inline operator const {c_type(api, name)}&() const noexcept;")
    lines.append("")
    if j.get("extensible"):
        lines.append("    ChainedStructOut * nextInChain = nullptr;" if out else
                     "    ChainedStruct const * nextInChain = nullptr;")
    lines += struct_members(api, name, free)
    if free:
        lines += ["", "  private:", "    inline void FreeMembers();", f"    static inline void Reset({cpp}& value);"]
    lines.append("};")
    return "\n".join(lines)


def layout_asserts(api, name, cpp, ctype):
    lines = [f'static_assert(sizeof({cpp}) == sizeof({ctype}), "sizeof mismatch for {cpp}");',
             f'static_assert(alignof({cpp}) == alignof({ctype}), "alignof mismatch for {cpp}");']
    fields = (["nextInChain"] if api.json[name].get("extensible") else []) + \
        [camelCase(m["name"]) for m in api.members(name)]
    for f in fields:
        lines.append(f'static_assert(offsetof({cpp}, {f}) == offsetof({ctype}, {f}), "offsetof mismatch for {cpp}::{f}");')
    return lines


def free_members_impl(api, name, cpp):
    members = api.members(name)
    names = (["nextInChain"] if api.json[name].get("extensible") else []) + [camelCase(m["name"]) for m in members]
    checks = []
    for m in members:
        if m.get("annotation", "value") != "value":
            checks.append(f"this->{camelCase(m['name'])} != nullptr")
        elif m["type"] == "string view":
            checks.append(f"this->{camelCase(m['name'])}.data != nullptr")
    writable = {"nextInChain"}  # the chain pointer is the caller's; the rest is const
    moves = "".join(f"    {n} = rhs.{n};\n" if n in writable else f"    detail::AsNonConstReference({n}) = rhs.{n};\n"
                    for n in names)
    resets = "".join(f"    value.{n} = defaults.{n};\n" if n in writable else
                     f"    detail::AsNonConstReference(value.{n}) = defaults.{n};\n" for n in names)
    return (f"{cpp}::{cpp}() = default;\n"
            f"{cpp}::~{cpp}() {{ FreeMembers(); }}\n"
            f"{cpp}::{cpp}({cpp}&& rhs)\n    : {', '.join(f'{n}(rhs.{n})' for n in names)} {{\n    Reset(rhs);\n}}\n"
            f"{cpp}& {cpp}::operator=({cpp}&& rhs) {{\n    if (&rhs == this) return *this;\n    FreeMembers();\n"
            f"{moves}    Reset(rhs);\n    return *this;\n}}\n"
            f"void {cpp}::FreeMembers() {{\n    if ({' || '.join(checks)}) {{\n"
            f"        wgpu{CamelCase(name)}FreeMembers(*reinterpret_cast<{c_type(api, name)}*>(this));\n    }}\n}}\n"
            f"void {cpp}::Reset({cpp}& value) {{\n    {cpp} defaults;\n{resets}}}\n")


def chained_impl(api, name, cpp):
    out = "Out" if api.is_output(name) else ""
    const = "" if out else " const"
    members = api.members(name)
    init_members = "".join(f"    {cpp_annotated(api, m)} {camelCase(m['name'])}{member_default(api, name, m, False)};\n"
                           for m in members)
    inits = "".join(f", {camelCase(m['name'])}(std::move(init.{camelCase(m['name'])}))" for m in members)
    return (f"{cpp}::{cpp}() : ChainedStruct{out}{{nullptr, SType::{CamelCase(name)}}} {{}}\n"
            f"struct {cpp}::Init {{\n    ChainedStruct{out}{const} * nextInChain;\n{init_members}}};\n"
            f"{cpp}::{cpp}({cpp}::Init&& init)\n    : ChainedStruct{out}{{init.nextInChain, SType::{CamelCase(name)}}}{inits} {{}}\n")


def struct_impl(api, name):
    cpp, ctype = cpp_type(api, name), c_type(api, name)
    lines = [f"// {cpp}"]
    if api.json[name].get("chained"):
        lines.append(chained_impl(api, name, cpp))
    if api.has_free_members(name):
        lines.append(free_members_impl(api, name, cpp))
    lines.append(f"{cpp}::operator const {ctype}&() const noexcept {{ return *reinterpret_cast<const {ctype}*>(this); }}")
    lines += layout_asserts(api, name, cpp, ctype)
    return "\n".join(lines)


def enum_decl(api, name):
    cpp, ctype = cpp_type(api, name), c_type(api, name)
    underlying = "uint64_t" if api.types[name] == "bitmask" else "uint32_t"
    lines = [f"enum class {cpp} : {underlying} {{"]
    for v in api.enum_values(name):
        lines.append(f"    {cpp_enum_name(v['name'])} = {ctype}_{CamelCase(v['name'])},")
    lines += ["};", f'static_assert(sizeof({cpp}) == sizeof({ctype}), "sizeof mismatch for {cpp}");']
    return "\n".join(lines)


def constants(api):
    lines = []
    for name, c in api.constants().items():
        value = c.get("cpp_value") or f"WGPU_{'_'.join(x.upper() for x in name.split(' '))}"
        lines.append(f"static constexpr {c['type']} k{CamelCase(name)} = {value};")
    return "\n".join(lines)


# Structures the C++ API shows in another form: StringView and DeviceDescriptor are
# written by hand (cpp_support), callback infos are filled inside the callback methods.
def plain_structures(api):
    return [s for s in api.order
            if s not in ("string view", "device descriptor") and api.types[s] == "structure"]


def write(api, revision_note):
    enums = [e for e in api.of_category("enum") if e != "optional bool"]
    out = [cpp_support.HEADER_COMMENT.format(revision=revision_note), cpp_support.INCLUDES,
           "namespace wgpu {", "", constants(api), ""]
    out += [enum_decl(api, e) + "\n" for e in enums + api.of_category("bitmask")]
    out += [f"template <>\nstruct IsWGPUBitmask<{cpp_type(api, b)}> {{\n    static constexpr bool enable = true;\n}};\n"
            for b in api.of_category("bitmask")]
    out += [f"class {cpp_type(api, o)};" for o in api.of_category("object")]
    out += [f"struct {cpp_type(api, s)};" for s in api.order if api.types[s] == "structure"]
    out += ["", cpp_support.BASICS, cpp_methods.callback_aliases(api), ""]
    out += [cpp_methods.class_decl(api, o) for o in api.of_category("object")]
    out += ["", "#if defined(__GNUC__) || defined(__clang__)", "#pragma GCC diagnostic push",
            '#pragma GCC diagnostic ignored "-Winvalid-offsetof"', "#endif", ""]
    out += [struct_decl(api, s) + "\n" for s in plain_structures(api)]
    out += [cpp_support.DEVICE_DESCRIPTOR]
    out += [struct_impl(api, s) + "\n" for s in plain_structures(api)]
    out += [cpp_support.DEVICE_DESCRIPTOR_IMPL]
    out += ["#if defined(__GNUC__) || defined(__clang__)", "#pragma GCC diagnostic pop", "#endif", ""]
    out += [cpp_methods.class_impl(api, o) for o in api.of_category("object")]
    out += [cpp_methods.functions_impl(api), "}  // namespace wgpu", "", "#endif  // WEBGPU_CPP_H_", ""]
    return "\n".join(out)
