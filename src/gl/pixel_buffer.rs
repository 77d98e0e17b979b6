//! Pixel buffer objects (ARB_pixel_buffer_object): where a pixel command's
//! image lives. With a buffer bound to PIXEL_UNPACK_BUFFER, the commands
//! that take an image (glDrawPixels, glBitmap, glPolygonStipple,
//! glPixelMap, glTexImage*, glTexSubImage*, glColorTable and the other
//! imaging uploads) read it from that buffer's store, their pointer
//! argument being an offset into it; with one bound to PIXEL_PACK_BUFFER,
//! the commands that return an image (glReadPixels, glGetTexImage,
//! glGetPolygonStipple, glGetPixelMap, glGetColorTable and the other
//! imaging readbacks) write it there.
//!
//! The extension's errors: INVALID_OPERATION when the buffer is mapped, or
//! when the bytes the command would touch (from the offset to the end of
//! the last group, as the pack/unpack modes lay the image out) do not fit
//! in the store. Nothing is read or written then.
//!
//! The pointer returned points into the store's `Vec`, which is not
//! reallocated while the command runs (only glBufferData and deletion
//! replace it), so the packing and unpacking code reads and writes it as it
//! does client memory.

use super::buffers::Buffer;
use super::context::Context;
use super::enums::GL_INVALID_OPERATION;
use super::pixel_data::Layout;
use super::pixels::PixelModes;

/// Bytes a w x h x d image of `format`/`ty` spans from its pointer, as
/// `modes` lay it out (0 for an empty image).
pub fn image_extent(modes: &PixelModes, w: i32, h: i32, d: i32, format: u32, ty: u32) -> usize {
    let [w, h, d] = [w, h, d].map(|s| s.max(0) as usize);
    Layout::new(modes, w, h, format, ty).extent(w, h, d)
}

/// Checks that `extent` bytes at `offset` of a pixel buffer may be
/// accessed, or gives the extension's INVALID_OPERATION.
fn check_range(b: &Buffer, offset: usize, extent: usize) -> Result<(), u32> {
    // An empty image touches nothing, wherever its offset points.
    if b.mapped || (extent > 0 && offset.checked_add(extent).is_none_or(|end| end > b.data.len())) {
        return Err(GL_INVALID_OPERATION);
    }
    Ok(())
}

impl Context {
    /// Is a pixel unpack buffer bound (pointers are offsets)?
    pub fn unpack_buffer_bound(&self) -> bool {
        self.buffers.pixel_unpack != 0
    }

    /// Is a pixel pack buffer bound (pointers are offsets)?
    pub fn pack_buffer_bound(&self) -> bool {
        self.buffers.pixel_pack != 0
    }

    /// The memory an unpacking command reads `extent` bytes from: `ptr`
    /// itself with no PIXEL_UNPACK_BUFFER bound, else the bound buffer's
    /// store at offset `ptr` (Err: the GL error to raise).
    pub fn unpack_source(&self, ptr: *const u8, extent: usize) -> Result<*const u8, u32> {
        let name = self.buffers.pixel_unpack;
        if name == 0 {
            return Ok(ptr);
        }
        let b = self.buffers.get(name).ok_or(GL_INVALID_OPERATION)?;
        check_range(b, ptr as usize, extent)?;
        // Within the store when anything is read (checked); an empty
        // image's pointer is never dereferenced.
        Ok(b.data.as_ptr().wrapping_add(ptr as usize))
    }

    /// The memory a packing command writes `extent` bytes to: `ptr` with no
    /// PIXEL_PACK_BUFFER bound, else the bound buffer's store at offset `ptr`.
    pub fn pack_dest(&mut self, ptr: *mut u8, extent: usize) -> Result<*mut u8, u32> {
        let name = self.buffers.pixel_pack;
        if name == 0 {
            return Ok(ptr);
        }
        let b = self.buffers.get_mut(name).ok_or(GL_INVALID_OPERATION)?;
        check_range(b, ptr as usize, extent)?;
        // As in `unpack_source`.
        Ok(b.data.as_mut_ptr().wrapping_add(ptr as usize))
    }

    /// [`Self::unpack_source`] for an image laid out by the unpack modes.
    #[allow(clippy::too_many_arguments)]
    pub fn unpack_image(&self, modes: &PixelModes, w: i32, h: i32, d: i32, format: u32, ty: u32, ptr: *const u8) -> Result<*const u8, u32> {
        if self.buffers.pixel_unpack == 0 {
            return Ok(ptr);
        }
        self.unpack_source(ptr, image_extent(modes, w, h, d, format, ty))
    }

    /// [`Self::pack_dest`] for an image laid out by the pack modes.
    #[allow(clippy::too_many_arguments)]
    pub fn pack_image(&mut self, modes: &PixelModes, w: i32, h: i32, d: i32, format: u32, ty: u32, ptr: *mut u8) -> Result<*mut u8, u32> {
        if self.buffers.pixel_pack == 0 {
            return Ok(ptr);
        }
        self.pack_dest(ptr, image_extent(modes, w, h, d, format, ty))
    }
}
