//! The C ABI (DESIGN.md, "api/"). Every entry point of the library is one
//! line of the table in [`table`]; the `entry_points!` macro turns each line
//! into an exported `extern "system"` function, its display-list behaviour
//! and its slot in [`ENTRY_POINTS`], which GetProcAddress, the README's
//! coverage table and the header test all read. No GL logic lives here:
//! an entry point converts its C arguments and forwards.

pub mod args;
pub mod dispatch;
pub mod fpenv;
pub mod ret;
pub mod table;
pub mod types;

pub use table::ENTRY_POINTS;

/// How an entry point behaves, as declared in the table.
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A GL command that display lists record (GL 1.5 section 5.4); it builds
    /// a [`crate::gl::Command`], and whether it may appear between Begin and
    /// End is the command's own rule.
    list,
    /// Executes immediately, never compiled into a list; INVALID_OPERATION
    /// between Begin and End.
    exec,
    /// Client state (pixel store, arrays): immediate, never compiled;
    /// INVALID_OPERATION between Begin and End, as implementations do.
    client,
    /// A vertex-array draw (glArrayElement, glDrawArrays, glDrawElements
    /// and their range and multi forms). Not a [`crate::gl::Command`]
    /// itself: it reads client arrays, which a list must capture at
    /// compile time (section 5.4). The body calls a `Context::draw_*`
    /// method (gl::arrays) that, while a list is being compiled, records
    /// the vertex commands the draw generates, and otherwise (or also, in
    /// GL_COMPILE_AND_EXECUTE) feeds the arrays to primitive assembly. The
    /// method applies the Begin/End rule itself (glArrayElement is allowed
    /// between Begin and End, the others are not).
    draw,
    /// Needs no context: the window-system calls. The current context's
    /// binned triangles are shaded first (they present, resize and switch
    /// contexts).
    free,
    /// A GLU function: needs no context, and reaches GL only through the
    /// public entry points, which shade binned triangles where they must;
    /// so unlike `free` it leaves the batch open (a gluSphere between two
    /// others must not cost a hand-off to the tile workers).
    glu,
    /// Exported so programs link and load, but not implemented yet: does
    /// nothing and returns zero. Listed as such in the README.
    todo,
}

/// One row of the entry-point table.
pub struct EntryPoint {
    /// NUL-terminated name.
    pub name: &'static str,
    pub addr: *const (),
    pub kind: Kind,
    /// For an implemented entry point that does not yet do everything the
    /// spec asks: what is missing (`list["..."] glName(...)` in the table).
    pub partial: Option<&'static str>,
}

// SAFETY: the table is immutable and holds function addresses only.
unsafe impl Sync for EntryPoint {}

impl EntryPoint {
    pub fn name(&self) -> &'static str {
        &self.name[..self.name.len() - 1]
    }
}

/// Looks a name up in the table (GetProcAddress). Returns the address of
/// the exported function, for implemented and unimplemented entries alike.
pub fn proc_address(name: &[u8]) -> *const () {
    use std::collections::HashMap;
    use std::sync::OnceLock;
    // Addresses are kept as integers so the map is Sync.
    static INDEX: OnceLock<HashMap<&'static [u8], usize>> = OnceLock::new();
    let index = INDEX.get_or_init(|| {
        ENTRY_POINTS.iter().map(|e| (e.name().as_bytes(), e.addr as usize)).collect()
    });
    let found = |n: &[u8]| index.get(n).map(|&a| a as *const ());
    found(name).or_else(|| promoted_alias(name).and_then(found)).unwrap_or(std::ptr::null())
}

/// The core name of an extension entry point that GL promoted unchanged:
/// every ARB name of the extensions softgl advertises, and the EXT names
/// of those whose EXT form has the core signature (not, say,
/// EXT_vertex_array's glVertexPointerEXT, which takes a count).
fn promoted_alias(name: &[u8]) -> Option<&[u8]> {
    const EXT_PREFIXES: [&[u8]; 8] =
        [b"glBlend", b"glFogCoord", b"glSecondaryColor", b"glMultiDraw", b"glTexImage3D", b"glTexSubImage3D", b"glCopyTexSubImage3D", b"glDrawRangeElements"];
    if let Some(base) = name.strip_suffix(b"ARB") {
        return Some(base);
    }
    let base = name.strip_suffix(b"EXT")?;
    EXT_PREFIXES.iter().any(|p| base.starts_with(p)).then_some(base)
}

/// Reports an unimplemented entry point once per name when SOFTGL_DEBUG is set.
pub fn unimplemented(name: &'static str) {
    use std::sync::Mutex;
    static SEEN: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());
    if std::env::var_os("SOFTGL_DEBUG").is_none() {
        return;
    }
    if let Ok(mut seen) = SEEN.lock() {
        if !seen.contains(&name) {
            seen.push(name);
            eprintln!("softgl: {name} is not implemented yet");
        }
    }
}

/// Expands the table. See [`table`] for the syntax.
macro_rules! entry_points {
    ($( $kind:ident $([$note:literal])? $name:ident ( $($arg:ident : $ty:ty),* $(,)? ) $(-> $ret:ty)? $({ $($body:tt)* })? $(;)? )*) => {
        $( $crate::api::entry_point!($kind $name ( $($arg : $ty),* ) -> ($($ret)?) { $($($body)*)? }); )*

        /// Every entry point, in table order.
        pub static ENTRY_POINTS: &[$crate::api::EntryPoint] = &[$(
            $crate::api::EntryPoint {
                name: concat!(stringify!($name), "\0"),
                addr: $name as *const (),
                kind: $crate::api::Kind::$kind,
                partial: $crate::api::note!($($note)?),
            }
        ),*];
    };
}

macro_rules! entry_point {
    (list $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { |$c:ident| $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            // `move`: the closure holds the arguments' values (every C
            // argument is Copy), not their addresses, so they can stay in
            // registers (by reference glColor3f spilled its three floats
            // and stored their addresses: about 10 instructions a call).
            // The body may bail out with `?` (a NULL array) or `return None`
            // (an error it has set): then nothing is recorded or run.
            #[allow(unused_variables)]
            let build = move |$c: &mut $crate::gl::Context| -> Option<$crate::gl::Command> { Some($body) };
            $crate::api::dispatch::with_current_list(build)
        }
    };
    (exec $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { |$c:ident| $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            $crate::api::dispatch::outside_begin_end(|$c: &mut $crate::gl::Context| $body)
        }
    };
    (client $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { |$c:ident| $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            $crate::api::dispatch::outside_begin_end(|$c: &mut $crate::gl::Context| $body)
        }
    };
    (draw $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { |$c:ident| $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            $crate::api::dispatch::with_current(|$c: &mut $crate::gl::Context| $body)
        }
    };
    (free $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            $crate::api::dispatch::guarded(|| $body)
        }
    };
    (glu $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { $body:expr }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            $crate::api::dispatch::guarded_client(|| $body)
        }
    };
    (todo $name:ident ( $($arg:ident : $ty:ty),* ) -> $ret:ty { }) => {
        #[no_mangle]
        #[allow(unused_parens)]
        pub unsafe extern "system" fn $name($($arg: $ty),*) -> $ret {
            let _ = ($($arg,)*);
            $crate::api::unimplemented(stringify!($name));
            <$ret as $crate::api::ret::Zero>::zero()
        }
    };
}

macro_rules! note {
    () => {
        None
    };
    ($n:literal) => {
        Some($n)
    };
}

pub(crate) use entry_point;
pub(crate) use note;
pub(crate) use entry_points;
