{# `<prefix>_map_states`: each state's estimate from the map's rows (`lines`, one per state). -#}
/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void {{ prefix }}_map_states(const float *all, float *map) {
{{ lines }}}


