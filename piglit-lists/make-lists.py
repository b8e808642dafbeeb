#!/usr/bin/env python3
"""Writes the piglit test lists (gles2, gles3, gles31, raster, texture, gl3, gl4, xfb, smoke) from piglit's profiles.

usage: make-lists.py [--piglit DIR] [--out DIR] [--check]

The lists are selections of piglit's own `quick_gl`, `quick_shader` and `glslparser` profiles
(the names piglit uses with process isolation on), so they can be regenerated after a piglit
upgrade. --check only compares the lists in --out with what would be written (exit 1 when they
differ, e.g. in CI after a piglit upgrade).
"""
import argparse
import ast
import gzip
import os
import re
import sys
import xml.etree.ElementTree as ET

PIGLIT = "/usr/lib/x86_64-linux-gnu/piglit"
PIGLIT_BIN = os.path.join(PIGLIT, "bin")
PROFILES = ("quick_gl", "quick_shader", "glslparser")
HERE = os.path.dirname(os.path.abspath(__file__))


class Test:
    def __init__(self, name, profile, elem):
        self.name = name
        self.lname = name.lower()
        self.profile = profile
        self.opts = {o.get("name"): o.get("value") for o in elem.findall("option")}
        self.group = "@".join(name.split("@")[:2])
        cmd = self.opts.get("command")
        self.command = ast.literal_eval(cmd) if cmd else []
        self.program = self.command[0] if self.command else ""
        api_version = self.opts.get("api_version")
        self.api = ast.literal_eval(self.opts["api"]) if "api" in self.opts else None
        self.api_version = float(api_version) if api_version else None


def load(piglit):
    tests = []
    for p in PROFILES:
        root = ET.parse(gzip.open(os.path.join(piglit, "tests", p + ".xml.gz"))).getroot()
        tests += [Test(t.get("name"), p, t) for t in root.findall("Test")]
    return tests


# ------------------------------------------------------------------ GL ES
def parser_version(t):
    """GLSL ES version of a glslparsertest_gles2 test ('1.00', '3.00 es', '3.10'...)."""
    if t.program != "glslparsertest_gles2" or len(t.command) < 4:
        return None
    return float(t.command[3].split()[0])


def es_version(t):
    """Major GL ES version a test runs on, or None for a desktop GL (or EGL-only) test."""
    if t.group in ("spec@!opengl es 2.0", "spec@glsl-es-1.00"):
        return 2
    if t.group == "spec@!opengl es 3.0" or t.group.startswith("spec@glsl-es-3"):
        return 3
    v = parser_version(t)
    if v is not None:
        return 2 if v < 3 else 3
    if t.program == "shader_runner_gles2":
        return 2
    if t.program == "shader_runner_gles3":
        return 3
    # *_gles1/2/3 programs, and the others built against piglit's GL ES utility library
    return linked_es(t.program)


_LINKED = {}


def linked_es(program):
    """1, 2 or 3 when the program links piglit's GL ES 1/2/3 utility library (ES 1: our Mesa
    build has none, so in no list), else None."""
    if program not in _LINKED:
        _LINKED[program] = None
        path = os.path.join(PIGLIT_BIN, program)
        if program and os.path.isfile(path):
            with open(path, "rb") as f:
                data = f.read()
            for v in (1, 2, 3):
                if b"libpiglitutil_gles%d.so" % v in data:
                    _LINKED[program] = v
    return _LINKED[program]


# ------------------------------------------------------------------ desktop GL topics
# Groups whose GL version or feature set is within GL 2.1 / GLSL 1.20 (fixpipe's), searched by
# topic keyword: the bulk of both desktop lists.
CORE_GROUPS = re.compile(r"^(spec@!opengl [12]\.\d|shaders@|spec@glsl-1\.[12]0|hiz@"
                         r"|spec@arb_framebuffer_object|spec@ext_framebuffer_object"
                         r"|spec@arb_es2_compatibility)$")

# Families that are about something else and would dominate a list (hundreds of generated
# tests): left out of raster and texture, see docs/piglit.md.
OFF_TOPIC = re.compile(r"multisample|sample_shading|transform_feedback|geometry_shader"
                       r"|tessellation|compute|fp64|64bit|gpu_shader5|texture_gather"
                       r"|texture_view|cube_map_array|texture_barrier|bindless|spirv"
                       r"|image_load_store|dma_buf|external_objects|framebuffer_srgb"
                       r"|glx@|egl|wgl@")

RASTER_GROUPS = re.compile(r"^spec@(ext_packed_depth_stencil|oes_packed_depth_stencil"
                           r"|arb_depth_clamp|amd_depth_clamp_separate|ext_depth_bounds_test"
                           r"|arb_point_sprite|oes_point_sprite|arb_point_parameters"
                           r"|ext_polygon_offset_clamp|arb_provoking_vertex|ext_provoking_vertex"
                           r"|arb_draw_buffers_blend|ext_draw_buffers2|arb_clip_control"
                           r"|ext_frag_depth|arb_blend_func_extended)$")
RASTER_WORDS = re.compile(r"raster|fill|polygon|offset|depth|stencil|blend|logic-?op|scissor"
                          r"|point|(?<!pipe)(?<!in)line|clip|viewport|fragcoord|cull|front|provoking|triangle"
                          r"|quad|guardband|degenerate|early-z|colormask|color-mask|clear"
                          r"|dither|fragdepth|frag-depth|hiz|readpix|drawpix|copypix|bitmap"
                          r"|primitive|prim|winding|two-sided")

TEXTURE_GROUPS = re.compile(r"^spec@(arb_texture_cube_map|arb_seamless_cube_map"
                            r"|amd_seamless_cubemap_per_texture|arb_texture_rectangle"
                            r"|arb_depth_texture|arb_fragment_program_shadow|arb_texture_float"
                            r"|oes_texture_float|arb_texture_rg|ext_texture_srgb"
                            r"|ext_texture_snorm|ext_packed_float|ext_texture_shared_exponent"
                            r"|ext_texture_compression_s3tc|ext_texture_compression_rgtc"
                            r"|ext_texture_compression_latc|arb_texture_compression"
                            r"|oes_compressed_etc1_rgb8_texture|ext_texture_swizzle"
                            r"|ext_texture_lod_bias|arb_shader_texture_lod|sgis_generate_mipmap"
                            r"|arb_sampler_objects|ext_texture_integer|arb_texture_rgb10_a2ui"
                            r"|ext_texture_format_bgra8888|arb_texture_storage"
                            r"|ext_texture_env_combine|nv_texture_env_combine4"
                            r"|arb_texture_env_crossbar|arb_texture_query_lod"
                            r"|arb_texture_query_levels|arb_texture_non_power_of_two)$")
TEXTURE_WORDS = re.compile(r"(?<!ver)tex|mipmap|cube|npot|sampler|shadow|wrap|filter|lod|border"
                           r"|swizzle|compress|s3tc|rgtc|format|aniso|rectangle")
# texelFetch is GLSL 1.30 / EXT_gpu_shader4: asked for by name.
TEXELFETCH = re.compile(r"^spec@(glsl-1\.30|ext_gpu_shader4)@.*texelfetch")


def desktop(t):
    return es_version(t) is None and t.program != "glslparsertest" and \
        t.profile != "glslparser" and not OFF_TOPIC.search(t.lname)


def in_raster(t):
    if not desktop(t):
        return False
    if RASTER_GROUPS.match(t.group):
        return True
    return bool(CORE_GROUPS.match(t.group) and RASTER_WORDS.search(t.lname))


XFB_GROUPS = re.compile(r"^spec@(ext_transform_feedback|arb_transform_feedback[23]"
                        r"|arb_transform_feedback_overflow_query)$")


def in_xfb(t):
    """Transform feedback is off topic for raster and texture, not here."""
    return es_version(t) is None and t.program != "glslparsertest" and \
        t.profile != "glslparser" and bool(XFB_GROUPS.match(t.group))


# Desktop GL 3.1 to 3.3 and GLSL 1.40 to 3.30, the versions fixpipe exposes: their own groups and
# the extensions they are made of.  Left out: the glslparser profile and the generated
# built-in-function tests (the compiler's, not the model's: thousands of them), and the depth
# clamp and seamless cube map groups, which raster and texture run.
GL3_GROUPS = re.compile(r"^spec@(!opengl 3\.[123]|glsl-1\.[45]0|glsl-3\.30|arb_texture_buffer_object"
                        r"|arb_texture_buffer_range|arb_uniform_buffer_object"
                        r"|arb_explicit_attrib_location|arb_shader_bit_encoding|arb_occlusion_query2"
                        r"|arb_timer_query|arb_sync|arb_texture_multisample"
                        r"|arb_draw_elements_base_vertex|arb_fragment_coord_conventions"
                        r"|arb_instanced_arrays|arb_vertex_type_2_10_10_10_rev"
                        r"|arb_geometry_shader4)$")


def in_gl3(t):
    return es_version(t) is None and t.profile != "glslparser" and \
        bool(GL3_GROUPS.match(t.group)) and "built-in-functions" not in t.lname


# Desktop GL 4.0 and GLSL 4.00, the version fixpipe exposes above them: their own groups and the
# extensions GL 4.0 is made of.  The generated textureGather tests stay: each is a gather through
# the modeled unit's footprint, with constant, per-pixel and four offsets.  Left out as for gl3:
# the glslparser profile and the generated built-in-function tests.
GL4_GROUPS = re.compile(r"^spec@(!opengl 4\.0|glsl-4\.00|arb_gpu_shader5|arb_gpu_shader_fp64"
                        r"|arb_tessellation_shader|arb_sample_shading|arb_texture_cube_map_array"
                        r"|arb_texture_query_lod|arb_draw_buffers_blend|arb_draw_indirect"
                        r"|arb_texture_buffer_object_rgb32|arb_texture_gather"
                        r"|arb_shader_subroutine)$")


def in_gl4(t, elsewhere):
    return es_version(t) is None and t.profile != "glslparser" and \
        bool(GL4_GROUPS.match(t.group)) and "built-in-functions" not in t.lname and \
        t.name not in elsewhere


def in_texture(t):
    if not desktop(t):
        return False
    if TEXTURE_GROUPS.match(t.group) or TEXELFETCH.match(t.lname):
        return True
    return bool(CORE_GROUPS.match(t.group) and TEXTURE_WORDS.search(t.lname))


# ------------------------------------------------------------------ smoke
# The CI subset: every test here must pass (or be an expected failure) on all three drivers and
# run in well under a second through fixpipe. The first block is the original smoke list.
SMOKE = """
# rasterization rules
spec@!opengl 1.4@triangle-rasterization
spec@!opengl 1.4@triangle-rasterization-overdraw
spec@!opengl 1.1@fragment-center
spec@!opengl 1.1@degenerate-prims
spec@!opengl 1.1@triangle-guardband-viewport
spec@!opengl 1.1@polygon-offset
spec@!opengl 1.0@gl-1.0-polygon-line-aa
spec@!opengl 1.0@gl-1.0-front-invalidate-back
spec@!opengl 1.1@polygon-mode
spec@!opengl 1.4@triangle-rasterization-fbo
spec@!opengl 1.4@gl-1.4-polygon-offset
spec@!opengl 1.1@line-flat-clip-color
spec@!opengl 1.1@linestipple
spec@!opengl 2.0@gl-2.0-edgeflag
spec@!opengl 2.0@gl-2.0-edgeflag-immediate
spec@arb_provoking_vertex@arb-provoking-vertex-render
spec@ext_provoking_vertex@provoking-vertex
shaders@glsl-fs-fragcoord-zw-ortho
shaders@glsl-fs-fragcoord-zw-perspective
spec@!opengl 1.1@clipflat
spec@glsl-1.10@execution@clipping@clip-plane-transformation fixed
spec@!opengl 1.0@gl-1.0-beginend-coverage

# depth
spec@!opengl 1.1@depthfunc
spec@!opengl 1.1@depthrange-clear
spec@!opengl 1.1@readpix-z
spec@!opengl 2.0@early-z
spec@!opengl 1.1@depthstencil-default_fb-clear
spec@ext_packed_depth_stencil@fbo-clear-formats
spec@glsl-1.10@execution@interpolation@interpolation-none-gl_frontcolor-flat-fixed
spec@glsl-1.10@execution@interpolation@interpolation-none-gl_frontcolor-smooth-none
spec@ext_frag_depth@fragdepth_gles2
shaders@glsl-fs-fragcoord
spec@ext_framebuffer_object@fbo-depth-sample-compare

# stencil
spec@!opengl 1.4@stencil-wrap
spec@!opengl 2.0@gl-2.0-two-sided-stencil
spec@!opengl 1.1@stencil-drawpixels
spec@ext_packed_depth_stencil@fbo-stencil-gl_depth24_stencil8-clear

# blending
spec@!opengl 1.4@blendminmax
spec@!opengl 1.4@blendsquare
spec@ext_framebuffer_object@fbo-drawbuffers-blend-add
spec@ext_framebuffer_object@fbo-blending-formats
spec@!opengl 1.0@gl-1.0-blend-func
spec@arb_draw_buffers_blend@fbo-draw-buffers-blend

# scissor and clears
spec@!opengl 1.0@gl-1.0-scissor-clear
spec@!opengl 1.0@gl-1.0-scissor-polygon
spec@!opengl 1.0@gl-1.0-scissor-many
spec@!opengl 1.0@gl-1.0-scissor-depth-clear
spec@!opengl 2.0@clear-varray-2.0
spec@!opengl 1.0@gl-1.0-scissor-offscreen
spec@!opengl 1.1@clear-accum

# read-back
spec@!opengl 1.0@gl-1.0-readpixsanity

# textures
spec@!opengl 1.0@gl-1.0-textured-triangle
spec@!opengl 1.1@texwrap 2d
spec@!opengl 1.1@texwrap 2d proj
spec@!opengl 1.1@getteximage-simple
spec@!opengl 1.1@max-texture-size-level
spec@!opengl 1.1@texsubimage
spec@!opengl 1.1@gl-1.1-xor-copypixels
spec@!opengl 2.0@tex3d-npot
spec@!opengl 1.2@tex3d
spec@!opengl 1.2@mipmap-setup
spec@!opengl 1.4@tex-miplevel-selection
spec@arb_texture_cube_map@cubemap
spec@arb_texture_cube_map@cubemap npot
spec@arb_texture_rectangle@texrect-many
spec@arb_depth_texture@depth-tex-modes
spec@arb_depth_texture@texdepth
spec@sgis_generate_mipmap@gen-nonzero-unit
spec@ext_texture_swizzle@depth_texture_mode_and_swizzle
shaders@glsl-fs-texturecube
shaders@glsl-lod-bias
spec@glsl-1.10@execution@samplers@glsl-fs-shadow2d
spec@glsl-1.10@execution@samplers@glsl-fs-sampler-numbering-2

# points and lines
spec@!opengl 1.1@lineloop
spec@!opengl 1.1@point-line-no-cull
spec@!opengl 2.0@gl-2.0-large-point-fs
spec@!opengl 1.0@gl-1.0-long-line-loop
spec@!opengl 1.1@line-aa-width
spec@arb_point_sprite@arb_point_sprite-checkerboard
spec@arb_point_sprite@arb_point_sprite-mipmap
spec@arb_point_parameters@arb_point_parameters-point-attenuation
spec@!opengl 2.0@vs-point_size-zero
shaders@glsl-vs-point-size

# GLSL 1.10/1.20 basics
shaders@glsl-fs-loop
shaders@glsl-vs-loop
shaders@glsl-fs-discard-02
shaders@glsl-routing
shaders@glsl-novertexdata
shaders@glsl-fs-flat-color
spec@glsl-1.10@execution@built-in-functions@fs-dot-vec4-vec4
spec@glsl-1.20@execution@fs-nan-builtin-max
spec@glsl-1.10@execution@varying-packing@simple vec4 array

# GL ES 2.0
spec@!opengl es 2.0@glsl-fs-pointcoord
spec@!opengl es 2.0@fbo_discard_gles2
spec@!opengl es 2.0@multiple-shader-objects_gles2
spec@!opengl es 2.0@minmax_gles2
spec@glsl-es-1.00@built-in constants
spec@!opengl es 2.0@draw_buffers_gles2
spec@!opengl es 2.0@link-no-vsfs
spec@arb_es2_compatibility@arb_es2_compatibility-depthrangef
spec@arb_es2_compatibility@fbo-missing-attachment-clear
spec@glsl-es-1.00@execution@glsl-no-vertex-attribs
spec@glsl-es-1.00@execution@sanity
spec@glsl-es-1.00@compiler@version-macro.frag

# fragment shaders reading an input array at a run-time index: the compiled path leaves them to
# tgsi_exec (gallivm's code generation crashed on them; CI runs smoke with jitall too)
spec@glsl-1.50@execution@compatibility@gs-texcoord-array
spec@glsl-1.50@execution@compatibility@vs-gs-texcoord-array
"""


def write(path, header, names, check):
    text = header + "".join(n + "\n" for n in names)
    if check:
        old = open(path, encoding="utf-8").read() if os.path.exists(path) else ""
        if old != text:
            print(f"make-lists: {path} is out of date")
            return 1
        return 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"make-lists: {os.path.relpath(path)}: {len(names)} tests")
    return 0


def es31(t):
    """A GL ES 3.x test that needs GL ES 3.1 (GLSL ES 3.10): the parser tests of that version,
    the programs asking for an ES 3.1 context, the glsl-es-3.10 group; a subset of gles3."""
    return es_version(t) == 3 and (parser_version(t) == 3.1 or t.api_version == 3.1
                                   or t.group == "spec@glsl-es-3.10")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--piglit", default=PIGLIT)
    ap.add_argument("--out", default=HERE)
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()

    global PIGLIT_BIN
    PIGLIT_BIN = os.path.join(args.piglit, "bin")
    tests = load(args.piglit)
    by_name = {t.name: t for t in tests}
    gen = "# Generated by piglit-lists/make-lists.py from piglit's {} profiles: do not edit.\n"

    # gl4 leaves out what the texture and raster lists run already
    in_other = {t.name for t in tests if in_texture(t) or in_raster(t)}
    lists = {
        "gles2": ([t.name for t in tests if es_version(t) == 2],
                  "# Every piglit test that runs on a GL ES 2.0 context.\n"),
        "gles3": ([t.name for t in tests if es_version(t) == 3],
                  "# Every piglit test that runs on a GL ES 3.x context.\n"),
        "gles31": ([t.name for t in tests if es31(t)],
                   "# The GL ES 3.x tests that need GL ES 3.1 (GLSL ES 3.10): compute shaders,\n"
                   "# storage buffers, images, atomics, gather; a subset of gles3.\n"),
        "raster": ([t.name for t in tests if in_raster(t)],
                   "# Desktop GL tests about rasterization, depth, stencil, blending, scissor,\n"
                   "# points, lines, clipping and viewport (see docs/piglit.md).\n"),
        "texture": ([t.name for t in tests if in_texture(t)],
                    "# Desktop GL tests about textures: formats, wrap, filtering, mipmaps, cube\n"
                    "# maps, NPOT, LOD, texelFetch, shadow samplers (see docs/piglit.md).\n"),
        "gl3": ([t.name for t in tests if in_gl3(t)],
                "# Desktop GL 3.1 to 3.3 and GLSL 1.40 to 3.30: texture buffers, uniform blocks,\n"
                "# geometry shaders and layered rendering, multisample textures, sync objects\n"
                "# (see docs/piglit.md).\n"),
        "gl4": ([t.name for t in tests if in_gl4(t, in_other)],
                "# Desktop GL 4.0 and GLSL 4.00: gpu_shader5 (interpolateAt*, gather offsets,\n"
                "# vertex streams), doubles, tessellation, sample shading, cube map arrays,\n"
                "# textureGather; tests of the other lists left out (see docs/piglit.md).\n"),
        "xfb": ([t.name for t in tests if in_xfb(t)],
                "# Desktop GL tests of transform feedback: EXT_transform_feedback,\n"
                "# ARB_transform_feedback2/3, the overflow queries (see docs/piglit.md).\n"),
    }
    status = 0
    for name, (names, what) in lists.items():
        profiles = sorted({by_name[n].profile for n in names})
        status |= write(os.path.join(args.out, name + ".txt"),
                        gen.format(", ".join(profiles)) + what, sorted(names), args.check)

    # The smoke list keeps its sections and comments; every name must exist in the profiles.
    missing = [ln for ln in SMOKE.splitlines() if ln and not ln.startswith("#")
               and ln not in by_name]
    if missing:
        sys.exit("make-lists: smoke names not in piglit's profiles:\n  " + "\n  ".join(missing))
    smoke_names = [ln for ln in SMOKE.splitlines() if ln and not ln.startswith("#")]
    header = (gen.format("quick_gl/quick_shader/glslparser") +
              "# Smoke list: the CI subset (./fixpipe check).\n")
    text = SMOKE.lstrip("\n")
    if args.check:
        old = open(os.path.join(args.out, "smoke.txt"), encoding="utf-8").read()
        status |= old != header + "\n" + text
    else:
        with open(os.path.join(args.out, "smoke.txt"), "w", encoding="utf-8") as f:
            f.write(header + "\n" + text)
        print(f"make-lists: smoke.txt: {len(smoke_names)} tests")
    return status


if __name__ == "__main__":
    sys.exit(main())
