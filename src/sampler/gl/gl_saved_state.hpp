// The caller's OpenGL state that a patch sampler pass changes, captured before the pass and
// restored after it (GlSamplerOptions::use_current_context renders in the caller's context).
#pragma once

#include <epoxy/gl.h>

namespace asperity::glpatch {

// The clip distances of patch.vert.glsl that keep each triangle inside its tile.
inline constexpr int kTileClipPlanes = 4;

// The caller's GL state that a pass changes (for use_current_context), restored afterwards.
struct SavedState {
  GLint draw_fbo = 0, read_fbo = 0, program = 0, vao = 0, array_buffer = 0, active_texture = 0;
  GLint viewport[4] = {0, 0, 0, 0};
  GLboolean depth_test = GL_FALSE, cull_face = GL_FALSE, blend = GL_FALSE;
  GLboolean clip[kTileClipPlanes] = {};
  GLint depth_func = GL_LESS;

  static SavedState capture() {
    SavedState s;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.draw_fbo);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.read_fbo);
    glGetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vao);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &s.array_buffer);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &s.active_texture);
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &s.depth_func);
    s.depth_test = glIsEnabled(GL_DEPTH_TEST);
    s.cull_face = glIsEnabled(GL_CULL_FACE);
    s.blend = glIsEnabled(GL_BLEND);
    for (int i = 0; i < kTileClipPlanes; ++i) s.clip[i] = glIsEnabled(GL_CLIP_DISTANCE0 + i);
    return s;
  }
  void restore() const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fbo));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo));
    glUseProgram(static_cast<GLuint>(program));
    glBindVertexArray(static_cast<GLuint>(vao));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer));
    glActiveTexture(static_cast<GLenum>(active_texture));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glDepthFunc(static_cast<GLenum>(depth_func));
    auto set = [](GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); };
    set(GL_DEPTH_TEST, depth_test);
    set(GL_CULL_FACE, cull_face);
    set(GL_BLEND, blend);
    for (int i = 0; i < kTileClipPlanes; ++i) set(GL_CLIP_DISTANCE0 + i, clip[i]);
  }
};

}  // namespace asperity::glpatch
