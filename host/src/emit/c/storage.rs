//! The Rust static library's C interface (`c/include/<name>.h` of a crate `gen --spec` writes,
//! `crate::standalone::c_library`) over the C source's chosen kind: the same calls, statuses, storage
//! mark and checks, so that a firmware moves between the two C routes without changing a line.

use crate::spec::Design;

/// Bytes the observer of `design` needs at most on any target: the window (`N` samples of `f32`
/// outputs and inputs, twice, and two indices), the follower's state, covariance and start-up
/// constants, and slack for indices and padding. Both routes state it as `<NAME>_STORAGE_SIZE`; each
/// checks when it compiles that its observer fits.
pub fn storage_bound(design: &Design) -> usize {
    let (n, ny, nu) = (
        design.map.horizon,
        design.model.outputs.len(),
        design.model.inputs.len(),
    );
    let (nx, nt) = (design.model.states.len(), design.targets.len());
    let window = 2 * 4 * n * (ny + nu) + 2 * 8;
    let follower = 4 * (nx * (nx + 7) + 4 * nt) + 64;
    // The storage's mark and size before the observer.
    (MARK_BYTES + window + follower).div_ceil(8) * 8
}

/// Bytes before the observer in the C storage: the mark that `init` made an observer there, and the
/// size it was given.
pub const MARK_BYTES: usize = 16;

/// The mark of an observer of design `name` in C storage: FNV-1a of the name, never 0, so that
/// zeroed storage, storage `init` refused, or another design's observer are told apart.
pub fn mark(name: &str) -> u64 {
    let hash = name.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    hash | 1
}

/// The header's and the source's parts of the interface for `design`.
pub(super) fn storage_interface(design: &Design) -> (String, String) {
    let name = design.name.as_str();
    let inputs = design.model.inputs.len();
    let upper = name.to_uppercase();
    let bound = storage_bound(design);
    let header = format!(
        "/* The Rust static library's interface (c/include/{name}.h of a crate `mho gen --spec` writes) over\n \
         * {name}_observer: the same calls, statuses ({name}_status) and flags ({name}_saturation), so\n \
         * that a firmware moves between the two routes without a change. The observer lives in storage you\n \
         * provide, {upper}_STORAGE_SIZE bytes aligned to {upper}_STORAGE_ALIGN: `init` writes a mark of the\n \
         * design and the size before it, and every call checks them first. */\n\
         #define {upper}_STORAGE_ALIGN 8\n\
         typedef struct {{\n\
         \x20   uint64_t mark;\n\
         \x20   uint64_t size;\n\
         \x20   {name}_observer observer;\n\
         }} {name}_stored;\n\
         #define {upper}_STORAGE_SIZE {bound}\n\
         /* Does not compile where the observer would not fit in {upper}_STORAGE_SIZE bytes. */\n\
         typedef char {name}_storage_fits[sizeof({name}_stored) <= {upper}_STORAGE_SIZE ? 1 : -1];\n\
         \n\
         /* A fresh observer in storage of `size` bytes; call it again to reset. */\n\
         {name}_status {name}_init(void *storage, size_t size);\n\
         /* {name}_observer_push on the observer in storage. */\n\
         {name}_status {name}_push(void *storage, const float *y, const float *u);\n\
         /* The estimates into estimates[{upper}_TARGETS] and, unless saturation is NULL, whether each was\n \
         * held at an end of its range into saturation[{upper}_TARGETS]. */\n\
         {name}_status {name}_estimate(void *storage, float *estimates, {name}_saturation *saturation);\n\
         /* Bytes the observer occupies with its mark. */\n\
         size_t {name}_storage_size(void);\n\n"
    );
    let inputs_check = if inputs > 0 { " || u == NULL" } else { "" };
    let source = format!(
        "/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */\n\
         #define STORAGE_MARK 0x{mark:016x}ull\n\
         \n\
         /* The observer in storage: {upper}_BAD_ARGUMENT for a null or misaligned pointer,\n\
         \x20* {upper}_NOT_INITIALISED where {name}_init did not make one (it reads the first 16 bytes only). */\n\
         static {name}_status stored_observer(void *storage, {name}_observer **observer) {{\n\
         \x20   {name}_stored *stored = ({name}_stored *)storage;\n\
         \x20   if (storage == NULL || (uintptr_t)storage % {upper}_STORAGE_ALIGN != 0u) {{\n\
         \x20       return {upper}_BAD_ARGUMENT;\n\
         \x20   }}\n\
         \x20   if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof({name}_stored)) {{\n\
         \x20       return {upper}_NOT_INITIALISED;\n\
         \x20   }}\n\
         \x20   *observer = &stored->observer;\n\
         \x20   return {upper}_OK;\n\
         }}\n\
         \n\
         {name}_status {name}_init(void *storage, size_t size) {{\n\
         \x20   {name}_stored *stored = ({name}_stored *)storage;\n\
         \x20   if (storage == NULL || size < sizeof({name}_stored) || (uintptr_t)storage % {upper}_STORAGE_ALIGN != 0u) {{\n\
         \x20       return {upper}_BAD_ARGUMENT;\n\
         \x20   }}\n\
         \x20   stored->mark = STORAGE_MARK;\n\
         \x20   stored->size = (uint64_t)size;\n\
         \x20   {name}_observer_init(&stored->observer);\n\
         \x20   return {upper}_OK;\n\
         }}\n\
         \n\
         {name}_status {name}_push(void *storage, const float *y, const float *u) {{\n\
         \x20   {name}_observer *observer = NULL;\n\
         \x20   const {name}_status found = stored_observer(storage, &observer);\n\
         \x20   if (found != {upper}_OK) {{\n\
         \x20       return found;\n\
         \x20   }}\n\
         \x20   if (y == NULL{inputs_check}) {{\n\
         \x20       return {upper}_BAD_ARGUMENT;\n\
         \x20   }}\n\
         \x20   return {name}_observer_push(observer, y, u);\n\
         }}\n\
         \n\
         {name}_status {name}_estimate(void *storage, float *estimates, {name}_saturation *saturation) {{\n\
         \x20   {name}_observer *observer = NULL;\n\
         \x20   {name}_saturation flags[{upper}_TARGETS];\n\
         \x20   const {name}_status found = stored_observer(storage, &observer);\n\
         \x20   if (found != {upper}_OK) {{\n\
         \x20       return found;\n\
         \x20   }}\n\
         \x20   if (estimates == NULL) {{\n\
         \x20       return {upper}_BAD_ARGUMENT;\n\
         \x20   }}\n\
         \x20   return {name}_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);\n\
         }}\n\
         \n\
         size_t {name}_storage_size(void) {{\n\
         \x20   return sizeof({name}_stored);\n\
         }}\n\
         \n\
         #undef STORAGE_MARK\n",
        mark = mark(name),
    );
    (header, source)
}

/// The design's sample period as a C `float` literal (`0.1f`): the shortest decimal that reads back
/// as its f32, as the Rust design file's `SAMPLE_PERIOD`; both C headers define it with this text.
pub fn sample_period(design: &Design) -> String {
    format!("{:?}f", design.tau as f32)
}
