/*
 * The three demo scenes.  Each draws into the current viewport, whose
 * width/height ratio is `aspect`, and leaves no state behind that another
 * scene depends on; everything is fixed (no time input), so every frame and
 * every driver gets the same geometry.
 */
#ifndef FP_SCENES_H
#define FP_SCENES_H

#include <GLES2/gl2.h>

struct fp_scenes {
   GLuint prog_color, prog_lit, prog_tex;
   GLuint fan_vbo, tris_vbo;
   GLsizei fan_verts, tris_verts;
   GLuint torus_vbo, torus_ibo;
   GLsizei torus_indices;
   GLuint floor_vbo, tex;
   GLint lit_mvp, lit_model, tex_mvp, tex_sampler, color_scale;
};

void fp_scenes_init(struct fp_scenes *s);
void fp_scenes_fini(struct fp_scenes *s);

/* (a) Gouraud triangles: a fan sharing edges, overlapping and thin ones. */
void fp_scene_gouraud(const struct fp_scenes *s, float aspect);
/* (b) A depth-tested, lit, rotated torus under perspective. */
void fp_scene_mesh(const struct fp_scenes *s, float aspect);
/* (c) A mipmapped checker floor under perspective, trilinear. */
void fp_scene_textured(const struct fp_scenes *s, float aspect);

#endif
