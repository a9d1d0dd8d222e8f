    slot = observer->next;
    for (i = 0u; i < {{ upper }}_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + {{ upper }}_HORIZON][i] = y[i];
    }
{%- if inputs %}
    for (i = 0u; i < {{ upper }}_INPUTS; ++i) {
        observer->u[slot][i] = u[i];
        observer->u[slot + {{ upper }}_HORIZON][i] = u[i];
    }
{%- else %}
    (void)u;
{%- endif %}
    observer->next = slot + 1u >= {{ upper }}_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < {{ upper }}_HORIZON);
    return {{ upper }}_OK;
{# The end of a map's `_push`, included by the float map's and the integer map's: the accepted sample
   stored twice in the window (so that the last N are contiguous from `next`), the write position and
   the count moved on, and OK returned. #}
