{# The Rust static library's interface over `<name>_observer`: its part of the source (`mark` in hex). -#}
/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */
#define STORAGE_MARK 0x{{ mark }}ull

/* The observer in storage: {{ upper }}_BAD_ARGUMENT for a null or misaligned pointer,
 * {{ upper }}_NOT_INITIALISED where {{ name }}_init did not make one (it reads the first 16 bytes only). */
static {{ name }}_status stored_observer(void *storage, {{ name }}_observer **observer) {
    {{ name }}_stored *stored = ({{ name }}_stored *)storage;
    if (storage == NULL || (uintptr_t)storage % {{ upper }}_STORAGE_ALIGN != 0u) {
        return {{ upper }}_BAD_ARGUMENT;
    }
    if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof({{ name }}_stored)) {
        return {{ upper }}_NOT_INITIALISED;
    }
    *observer = &stored->observer;
    return {{ upper }}_OK;
}

{{ name }}_status {{ name }}_init(void *storage, size_t size) {
    {{ name }}_stored *stored = ({{ name }}_stored *)storage;
    if (storage == NULL || size < sizeof({{ name }}_stored) || (uintptr_t)storage % {{ upper }}_STORAGE_ALIGN != 0u) {
        return {{ upper }}_BAD_ARGUMENT;
    }
    stored->mark = STORAGE_MARK;
    stored->size = (uint64_t)size;
    {{ name }}_observer_init(&stored->observer);
    return {{ upper }}_OK;
}

{{ name }}_status {{ name }}_push(void *storage, const float *y, const float *u) {
    {{ name }}_observer *observer = NULL;
    const {{ name }}_status found = stored_observer(storage, &observer);
    if (found != {{ upper }}_OK) {
        return found;
    }
    if (y == NULL{% if inputs %} || u == NULL{% endif %}) {
        return {{ upper }}_BAD_ARGUMENT;
    }
    return {{ name }}_observer_push(observer, y, u);
}

{{ name }}_status {{ name }}_estimate(void *storage, float *estimates, {{ name }}_saturation *saturation) {
    {{ name }}_observer *observer = NULL;
    {{ name }}_saturation flags[{{ upper }}_TARGETS];
    const {{ name }}_status found = stored_observer(storage, &observer);
    if (found != {{ upper }}_OK) {
        return found;
    }
    if (estimates == NULL) {
        return {{ upper }}_BAD_ARGUMENT;
    }
    return {{ name }}_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);
}

size_t {{ name }}_storage_size(void) {
    return sizeof({{ name }}_stored);
}

#undef STORAGE_MARK

