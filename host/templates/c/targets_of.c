{# `<prefix>_targets_of`: the targets of a follower's states (`inside`: every target inside, then
   `flagged`: each state's saturation where the state is a target; `unused`: none is). -#}
/* The targets of a follower's states, flagged with their states' saturation. */
static void {{ prefix }}_targets_of(const float *states, const {{ name }}_saturation *state_flags, const float *u,
                                float *values, {{ name }}_saturation *flags) {
{%- if unused %}
    (void)state_flags;
{%- endif %}
    targets(states, u, values);
{{ inside }}{{ flagged }}}


