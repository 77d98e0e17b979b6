//! Sampler-side copies of 2D RGBA8 levels laid out for the bilinear fetch
//! of the 8-wide textured kernel (`fragment::textured::avx2`), GL 1.5
//! section 3.8.8 (the 2x2 texels of LINEAR filtering).
//!
//! Each level of w x h texels is copied with one extra column on each side
//! and one extra row above and below, (w + 2) x (h + 2), holding what the
//! wrap mode of that axis reads there: for REPEAT column -1 is column
//! w - 1 and column w is column 0; for CLAMP_TO_EDGE they repeat columns 0
//! and w - 1 (rows alike). With i0' = i0 mod w (REPEAT) or
//! clamp(i0, -1, w - 1) (CLAMP_TO_EDGE) the bilinear footprint's two
//! texels of a row, i0 and i0 + 1 after wrapping, are then always
//! adjacent in memory: the kernel reads them with one 64-bit gather
//! element instead of two 32-bit ones, and needs no second wrap. The
//! texel values are the level's own, so filtering is unchanged bit for bit.
//!
//! Built lazily, once per [`super::UnitSampler`] (`UnitSampler::padded`):
//! validation builds a new sampler whenever a texture's images or
//! parameters change (TexImage, TexSubImage, CopyTex*, GENERATE_MIPMAP,
//! wrap modes), so a copy never outlives the images it was made from; a
//! small process-wide table keyed by the images themselves (held weakly:
//! `Arc::make_mut` then never mutates them in place) lets the samplers
//! that validation rebuilds for unrelated state changes reuse a copy.

use super::{Image, Texels};
use std::sync::{Arc, Mutex, OnceLock, Weak};

/// One padded level: texel (i, j), i in -1..=w, j in -1..=h, at
/// `(j + 1) * stride + i + 1`, as the little-endian u32 of its RGBA bytes.
#[derive(Debug)]
pub struct PaddedLevel {
    pub texels: Vec<u32>,
    /// w + 2.
    pub stride: i32,
    /// Bit k set: channel k (R, G, B, A) has one value in every texel of
    /// the level, `flat_value[k]` (as c / 255). Every bilinear footprint
    /// then filters to that value exactly (a + (a - a) w = a for the
    /// weights in [0, 1)), so the kernel skips the channel's conversions
    /// and lerps: opaque RGBA and RGB textures (alpha 255 throughout),
    /// 1x1 levels.
    pub flat: u8,
    pub flat_value: [f32; 4],
}

/// The padded copies of a sampler's levels (base first).
#[derive(Debug)]
pub struct Padded {
    pub levels: Vec<PaddedLevel>,
}

/// A sampler's lazily built copy; cloning a sampler starts a new (empty)
/// one, which the process-wide table may fill without copying.
#[derive(Default)]
pub struct PadCache(OnceLock<Option<Arc<Padded>>>);

impl Clone for PadCache {
    fn clone(&self) -> Self {
        PadCache::default()
    }
}

impl std::fmt::Debug for PadCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.get().is_some_and(|p| p.is_some()) { "PadCache(built)" } else { "PadCache" })
    }
}

impl PadCache {
    /// The copy of `levels` for the wrap modes `repeat`, built on first
    /// use; None unless every level is 8-bit RGBA without border.
    pub fn get(&self, levels: &[Arc<Image>], repeat: [bool; 2]) -> Option<&Padded> {
        self.0.get_or_init(|| shared(levels, repeat)).as_deref()
    }
}

struct Entry {
    images: Vec<Weak<Image>>,
    repeat: [bool; 2],
    padded: Arc<Padded>,
}

/// Copies made recently, at most this many kept.
const KEEP: usize = 8;

fn shared(levels: &[Arc<Image>], repeat: [bool; 2]) -> Option<Arc<Padded>> {
    static TABLE: Mutex<Vec<Entry>> = Mutex::new(Vec::new());
    let same = |e: &Entry| e.repeat == repeat && e.images.len() == levels.len() && e.images.iter().zip(levels).all(|(w, a)| std::ptr::eq(w.as_ptr(), Arc::as_ptr(a)) && w.strong_count() > 0);
    if let Ok(mut table) = TABLE.lock() {
        table.retain(|e| e.images.iter().all(|w| w.strong_count() > 0));
        if let Some(k) = table.iter().position(same) {
            let e = table.remove(k);
            let p = e.padded.clone();
            table.push(e);
            return Some(p);
        }
        let padded = Arc::new(build(levels, repeat)?);
        if table.len() >= KEEP {
            table.remove(0);
        }
        table.push(Entry { images: levels.iter().map(Arc::downgrade).collect(), repeat, padded: padded.clone() });
        return Some(padded);
    }
    build(levels, repeat).map(Arc::new)
}

/// The padded copies (see the module documentation). The copy is only an
/// optimization: when it cannot be allocated (`try_reserve`) this returns
/// None and the kernels read the plain levels, instead of aborting.
pub fn build(levels: &[Arc<Image>], repeat: [bool; 2]) -> Option<Padded> {
    let mut out = Vec::new();
    out.try_reserve_exact(levels.len()).ok()?;
    for img in levels {
        let Texels::Rgba8(tex) = &img.texels else { return None };
        let (w, h) = (img.width, img.height);
        if img.border != 0 || w <= 0 || h <= 0 || tex.len() < (w as usize) * (h as usize) {
            return None;
        }
        // Index of a padded row/column in the level, by the axis's wrap mode.
        let axis = |i: i32, n: i32, rep: bool| if rep { i.rem_euclid(n) } else { i.clamp(0, n - 1) };
        let stride = w + 2;
        let mut texels = Vec::new();
        texels.try_reserve_exact((stride as usize).checked_mul(h as usize + 2)?).ok()?;
        // Row by row: the padding texels, and the row itself as one copy
        // (round 9: per-texel wrapping was 13 M instructions of the textured
        // scene's first frame for its 512x512 mipmapped texture).
        let (left, right) = (axis(-1, w, repeat[0]) as usize, axis(w, w, repeat[0]) as usize);
        for j in -1..=h {
            let start = (axis(j, h, repeat[1]) * w) as usize;
            let row = &tex[start..start + w as usize];
            texels.push(u32::from_le_bytes(row[left]));
            texels.extend(row.iter().map(|&t| u32::from_le_bytes(t)));
            texels.push(u32::from_le_bytes(row[right]));
        }
        let (flat, flat_value) = flat_channels(&tex[..(w * h) as usize]);
        out.push(PaddedLevel { texels, stride, flat, flat_value });
    }
    Some(Padded { levels: out })
}

/// `PaddedLevel::flat` and `flat_value` of a level's texels (the padding
/// only repeats them).
fn flat_channels(tex: &[[u8; 4]]) -> (u8, [f32; 4]) {
    let Some(first) = tex.first() else { return (0, [0.0; 4]) };
    // The bits where any texel differs from the first.
    let f = u32::from_le_bytes(*first);
    let diff = tex.iter().fold(0, |d, t| d | (u32::from_le_bytes(*t) ^ f)).to_le_bytes();
    let flat = (0..4).filter(|&k| diff[k] == 0).fold(0, |m, k| m | 1 << k);
    let value = std::array::from_fn(|k| if flat & (1 << k) != 0 { first[k] as f32 / 255.0 } else { 0.0 });
    (flat, value)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::texture::Base;

    fn image(w: i32, h: i32, seed: u32) -> Arc<Image> {
        let texels = (0..w * h).map(|k| ((k as u32).wrapping_mul(2654435761) ^ seed).to_le_bytes()).collect();
        Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(texels)) })
    }

    /// Every padded texel is the level's texel at the wrapped indices, and
    /// the pair at (i0', j') is (i0, i0 + 1) wrapped, for both wrap modes.
    #[test]
    fn padding_follows_the_wrap_modes() {
        for (w, h) in [(8, 4), (1, 1), (5, 3), (1, 6)] {
            let img = image(w, h, 77);
            let Texels::Rgba8(tex) = &img.texels else { unreachable!() };
            for repeat in [[true, true], [false, false], [true, false], [false, true]] {
                let p = build(&[img.clone()], repeat).unwrap();
                let l = &p.levels[0];
                let wrap = |i: i32, n: i32, rep: bool| if rep { i.rem_euclid(n) } else { i.clamp(0, n - 1) };
                for j0 in -3..h + 3 {
                    for i0 in -3..w + 3 {
                        let ip = if repeat[0] { i0.rem_euclid(w) } else { i0.clamp(-1, w - 1) };
                        let jp = if repeat[1] { j0.rem_euclid(h) } else { j0.clamp(-1, h - 1) };
                        for (dj, dk) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                            let got = l.texels[((jp + 1 + dj) * l.stride + ip + 1 + dk) as usize];
                            let want = tex[(wrap(j0 + dj, h, repeat[1]) * w + wrap(i0 + dk, w, repeat[0])) as usize];
                            assert_eq!(got.to_le_bytes(), want, "{w}x{h} {repeat:?} ({i0}, {j0}) + ({dk}, {dj})");
                        }
                    }
                }
            }
        }
    }

    /// `flat_channels`: a channel is flat when every texel has its first
    /// texel's byte there (one differing bit breaks it), with that value
    /// as c / 255; a single texel is flat in all four.
    #[test]
    fn flat_channels_of_levels() {
        let (flat, v) = flat_channels(&[[1, 2, 3, 255], [4, 2, 3, 255], [1, 2, 131, 255]]);
        assert_eq!(flat, 0b1010);
        assert_eq!(v.map(f32::to_bits), [0.0, 2.0 / 255.0, 0.0, 1.0].map(f32::to_bits));
        assert_eq!(flat_channels(&[[9, 0, 7, 5]]), (0b1111, [9.0 / 255.0, 0.0, 7.0 / 255.0, 5.0 / 255.0]));
        assert_eq!(flat_channels(&[]).0, 0);
        assert_eq!(flat_channels(&[[0, 0, 0, 0x80], [0, 0, 0, 0]]).0, 0b0111);
        // Through `build`: only the level's own texels count.
        let img = image(5, 3, 3);
        assert_eq!(build(&[img], [true; 2]).unwrap().levels[0].flat, 0);
    }

    /// The shared table hands out the same copy for the same images and
    /// a new one for new images (a TexSubImage makes new ones while a
    /// copy is held).
    #[test]
    fn table_keys_on_the_images() {
        let (a, b) = (image(4, 4, 1), image(4, 4, 2));
        let pa = shared(&[a.clone()], [true; 2]).unwrap();
        assert!(Arc::ptr_eq(&pa, &shared(&[a.clone()], [true; 2]).unwrap()));
        assert!(!Arc::ptr_eq(&pa, &shared(&[a.clone()], [false; 2]).unwrap()));
        let pb = shared(&[b.clone()], [true; 2]).unwrap();
        assert_eq!(pb.levels[0].texels[7].to_le_bytes(), match &b.texels { Texels::Rgba8(t) => t[0], _ => unreachable!() });
        // Texel (0, 0) is at (0 + 1) * 6 + 0 + 1 in the padded copy.
        // make_mut copies an image the table knows (weakly).
        let mut a2 = a.clone();
        drop(a);
        let m = Arc::make_mut(&mut a2);
        if let Texels::Rgba8(t) = &mut m.texels {
            Arc::make_mut(t)[0] = [9, 9, 9, 9];
        }
        let p2 = shared(&[a2.clone()], [true; 2]).unwrap();
        assert_eq!(p2.levels[0].texels[7].to_le_bytes(), [9, 9, 9, 9]);
    }
}
