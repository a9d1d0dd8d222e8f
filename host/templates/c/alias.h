{# The header's name for the design's chosen kind (`<name>_observer`), or why there is none. -#}
{% if c_form -%}
/* This design's observer, of the kind `gen` chose or the spec named: {{ kind }}. */
#define {{ upper }}_KIND "{{ kind }}"
typedef {{ name }}_{{ kind }} {{ name }}_observer;
#define {{ name }}_observer_init {{ name }}_{{ kind }}_init
#define {{ name }}_observer_push {{ name }}_{{ kind }}_push
#define {{ name }}_observer_estimate {{ name }}_{{ kind }}_estimate

{% else -%}
/* This design's observer is of kind {{ kind }}, which has no C form: use the Rust crate. */
#define {{ upper }}_KIND "{{ kind }}"

{% endif %}
