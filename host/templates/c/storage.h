{# The Rust static library's interface over `<name>_observer`: its part of the header. -#}
/* The Rust static library's interface (c/include/{{ name }}.h of a crate `mho gen --spec` writes) over
 * {{ name }}_observer: the same calls, statuses ({{ name }}_status) and flags ({{ name }}_saturation), so
 * that a firmware moves between the two routes without a change. The observer lives in storage you
 * provide, {{ upper }}_STORAGE_SIZE bytes aligned to {{ upper }}_STORAGE_ALIGN: `init` writes a mark of the
 * design and the size before it, and every call checks them first. */
#define {{ upper }}_STORAGE_ALIGN 8
typedef struct {
    uint64_t mark;
    uint64_t size;
    {{ name }}_observer observer;
} {{ name }}_stored;
#define {{ upper }}_STORAGE_SIZE {{ bound }}
/* Does not compile where the observer would not fit in {{ upper }}_STORAGE_SIZE bytes. */
typedef char {{ name }}_storage_fits[sizeof({{ name }}_stored) <= {{ upper }}_STORAGE_SIZE ? 1 : -1];

/* A fresh observer in storage of `size` bytes; call it again to reset. */
{{ name }}_status {{ name }}_init(void *storage, size_t size);
/* {{ name }}_observer_push on the observer in storage. */
{{ name }}_status {{ name }}_push(void *storage, const float *y, const float *u);
/* The estimates into estimates[{{ upper }}_TARGETS] and, unless saturation is NULL, whether each was
 * held at an end of its range into saturation[{{ upper }}_TARGETS]. */
{{ name }}_status {{ name }}_estimate(void *storage, float *estimates, {{ name }}_saturation *saturation);
/* Bytes the observer occupies with its mark. */
size_t {{ name }}_storage_size(void);


