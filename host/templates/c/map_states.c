{# `<prefix>_map_states`: each state's estimate from the map's targets (`lines`, one per state). -#}
/* Each state's map estimate, from the map's targets. */
static void {{ prefix }}_map_states(const float *all, float *map) {
{{ lines }}}


