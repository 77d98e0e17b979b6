//! glDrawBuffer and glReadBuffer (GL 1.5 sections 4.2.1 and 4.3.2), and the
//! colour-index mode's glIndexMask / glClearIndex, which an RGBA context
//! stores and otherwise ignores.
//!
//! A single-buffered surface has one colour buffer, the front left one; a
//! double-buffered surface has a front and a back buffer (no stereo, no
//! aux buffers). Names that do not exist on the surface are
//! INVALID_OPERATION (RIGHT, AUXi, and BACK on a single-buffered surface);
//! GL_NONE disables colour writes. The framebuffer is pointed at the named
//! buffers lazily ([`Context::sync_draw_buffer`]) before anything draws,
//! clears or accumulates, so every path that changes the draw-buffer state
//! (glDrawBuffer, glPopAttrib, display lists) is covered by one call.

use super::context::Context;
use super::enums::*;
use super::validate::DIRTY_FRAGMENT;
use super::framebuffer_object::{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT15, MAX_COLOR_ATTACHMENTS};
use crate::framebuffer::DrawTarget;

pub const GL_NONE: u32 = 0;
pub const GL_FRONT_LEFT: u32 = 0x0400;
pub const GL_FRONT_RIGHT: u32 = 0x0401;
pub const GL_BACK_LEFT: u32 = 0x0402;
pub const GL_BACK_RIGHT: u32 = 0x0403;
pub const GL_LEFT: u32 = 0x0406;
pub const GL_RIGHT: u32 = 0x0407;
pub const GL_AUX0: u32 = 0x0409;

/// Is `mode` a colour-buffer name at all (else INVALID_ENUM)?
fn is_buffer_name(mode: u32) -> bool {
    matches!(mode, GL_NONE | GL_FRONT_LEFT..=GL_BACK_RIGHT | GL_FRONT | GL_BACK | GL_LEFT | GL_RIGHT | GL_FRONT_AND_BACK)
        || (GL_AUX0..GL_AUX0 + 4).contains(&mode)
        || (GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT15).contains(&mode)
}

impl Context {
    /// Does the surface have the buffer(s) `mode` names?
    fn buffer_exists(&self, mode: u32, fbo: bool) -> bool {
        if fbo {
            // A framebuffer object's buffers are its colour attachments
            // (EXT_framebuffer_object section 4.2.1).
            return mode == GL_NONE || (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + MAX_COLOR_ATTACHMENTS).contains(&mode);
        }
        match mode {
            GL_NONE | GL_FRONT_LEFT | GL_FRONT | GL_LEFT | GL_FRONT_AND_BACK => true,
            GL_BACK_LEFT | GL_BACK => self.double_buffered,
            // No stereo, no aux buffers.
            _ => false,
        }
    }

    pub fn draw_buffer(&mut self, mode: u32) {
        if !is_buffer_name(mode) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.buffer_exists(mode, self.fbo.draw_binding != 0) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.color_buffer.draw_buffer = mode;
        self.dirty |= DIRTY_FRAGMENT;
    }

    pub fn read_buffer(&mut self, mode: u32) {
        // NONE and FRONT_AND_BACK name no single buffer to read.
        let fbo = self.fbo.read_binding != 0;
        // NONE is a valid read buffer for a framebuffer object.
        if !is_buffer_name(mode) || (mode == GL_NONE && !fbo) || mode == GL_FRONT_AND_BACK {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.buffer_exists(mode, fbo) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.pixel_read_buffer = mode;
    }
}

impl Context {
    /// Points the framebuffer at the buffers the draw-buffer state names.
    pub fn sync_draw_buffer(&mut self) {
        let target = self.draw_target();
        self.fb.select_draw(target);
    }

    /// [`Self::sync_draw_buffer`] for a command that may record itself
    /// in the rasterizer's batch (round 13: glClear, glAccum) rather than
    /// sync first: when it would swap the colour buffers, whatever is
    /// binned is shaded first (it draws into the buffer drawn before).
    pub fn sync_draw_buffer_keeping_batch(&mut self) {
        let target = self.draw_target();
        if self.fb.select_swaps(target) {
            self.sync_render();
        }
        self.fb.select_draw(target);
    }

    /// The colour buffers the draw-buffer state names.
    fn draw_target(&self) -> DrawTarget {
        match self.color_buffer.draw_buffer {
            GL_FRONT | GL_FRONT_LEFT => DrawTarget::Front,
            GL_BACK | GL_BACK_LEFT => DrawTarget::Back,
            // Table 4.4: LEFT names the front and back left buffers.
            GL_FRONT_AND_BACK | GL_LEFT => DrawTarget::FrontAndBack,
            _ => DrawTarget::None,
        }
    }

    /// The colour buffer glReadBuffer names (FRONT and LEFT: the front
    /// left buffer, BACK the back left one; section 4.3.2): what glReadPixels,
    /// glCopyPixels, glCopyTexImage and glAccum read.
    pub fn read_color(&self) -> &[[u8; 4]] {
        self.fb.read_color(matches!(self.pixel_read_buffer, GL_BACK | GL_BACK_LEFT))
    }

    /// The read drawable's framebuffer (glXMakeContextCurrent's `read`;
    /// the draw framebuffer unless the window system set another) and its
    /// colour buffer glReadBuffer names: what glReadPixels, glCopyPixels
    /// and glCopyTexImage read.
    ///
    /// With framebuffer objects bound: the read object's staging buffer
    /// (the draw one's when they are the same), or the window's parked
    /// framebuffer when only the draw framebuffer is an object.
    pub fn read_source(&self) -> (&crate::framebuffer::Framebuffer, &[[u8; 4]]) {
        let (r, d) = (self.fbo.read_binding, self.fbo.draw_binding);
        if r != 0 {
            let fb = if r == d { &self.fb } else { self.fbo.read_staging.as_ref().unwrap_or(&self.fb) };
            return (fb, &fb.color);
        }
        let fb = self.read_fb.as_ref().or(self.fbo.parked.as_ref()).unwrap_or(&self.fb);
        (fb, fb.read_color(matches!(self.pixel_read_buffer, GL_BACK | GL_BACK_LEFT)))
    }
}
