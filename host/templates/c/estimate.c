{# `<name>_<kind>_estimate`: the latest accepted sample's targets, kept in `values` and `flags`. -#}
{{ name }}_status {{ name }}_{{ kind }}_estimate(const {{ name }}_{{ kind }} *o, float *values, {{ name }}_saturation *saturation) {
    if (!o->ready) {
        return {{ upper }}_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return {{ upper }}_OK;
}


