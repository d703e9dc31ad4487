# Sourced by the build and CI scripts: `stage NAME COMMAND...` runs COMMAND and prints its wall
# time at its end ("== stage: release build 6m12s"), so a slow step shows in every log;
# `stage_total` prints the time since the script started. A failing COMMAND fails the stage
# (its status is returned, and `set -e` stops the script there).
stage() {
    local name=$1 start=$SECONDS status=0
    shift
    echo "== stage: $name ..."
    "$@" || status=$?
    local took=$((SECONDS - start))
    if [ "$status" -eq 0 ]; then
        printf '== stage: %s %dm%02ds\n' "$name" $((took / 60)) $((took % 60))
    else
        printf '== stage: %s FAILED (status %d) after %dm%02ds\n' "$name" "$status" $((took / 60)) $((took % 60))
    fi
    return "$status"
}
stage_total() {
    printf '== total: %s %dm%02ds\n' "$1" $((SECONDS / 60)) $((SECONDS % 60))
}
