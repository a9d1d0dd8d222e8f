{# `<name>_<kind>_init` and `_push` of a filter kind over its own start and sample (`<kind>_fresh`,
   `<kind>_sample`), with its refusals and restarts counted in this one place, as
   `firmware::rules::Refusals` counts them on the Rust side. -#}
void {{ name }}_{{ kind }}_init({{ name }}_{{ kind }} *o) {
    {{ kind }}_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

{{ name }}_status {{ name }}_{{ kind }}_push({{ name }}_{{ kind }} *o, const float *y, const float *u) {
    const {{ name }}_status status = {{ kind }}_sample(o, y, u);
    if (status == {{ upper }}_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == {{ upper }}_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

{% include "c/estimate.c" %}
