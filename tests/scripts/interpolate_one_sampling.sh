#!/bin/sh
# interpolate_one_sampling.sh BUILD - gmat check's sampling properties over generated interpolate-one nodes that blend
# reflection or refraction alone: every pair of lambert, phong with a mirror term, mirror and glass (dielectric), in
# both orders, at t 0.3 and following v (so gmat check's places blend differently), in rgb and spectrum in turn.
# Such a node's reflection and refraction are different blends of its children (one of them the first child's
# alone), and a sample must weigh the value of the blend its flag names: before, every sample was drawn and weighed
# from the reflection's blend, so a glass whose refraction was blended with a lambert's (black) transmitted its full
# transmittance in sample() (weight 2 times value / pdf at t 0.5), and a lambert whose reflection was blended with a
# glass's never drew the glass's reflection. chi2, pdf integral and weight must pass; albedo is not asked (blending
# one method of two energy-conserving materials need not conserve energy: mirror reflection over a glass's
# refraction sends out more than arrives). About 10 s.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
OPTS=$(check_opts "$GMAT") # gmat check's options (prelude.sh)
cat > "$TMP/one.mat" << 'EOM'
material ll lambert { reflectance rgb 0.6 0.3 0.2 }
material pm phong { diffuse rgb 0.1 0.1 0.1 specular rgb 0.3 0.3 0.3 exponent 200 mirror rgb 0.3 0.3 0.3 }
material mr mirror { reflectance rgb 0.9 0.8 0.7 }
material glass dielectric { index 1.5 }
generator fixed constant { value 0.3 }
generator along gradient { space uv slope 0 1 0 }
EOM
: > "$TMP/nodes"
turn=0
for a in ll pm mr glass; do
    for b in ll pm mr glass; do
        [ "$a" = "$b" ] && continue
        for method in reflection refraction; do
            for t in fixed along; do
                name="${method}_${a}_${b}_$t"
                echo "node $name interpolate-one { a $a b $b t $t method $method }" >> "$TMP/one.mat"
                [ $((turn % 2)) -eq 0 ] && model=rgb || model=spectrum
                echo "$name $model" >> "$TMP/nodes"
                turn=$((turn + 1))
            done
        done
    done
done
checked=0
every=1
sanitized "$GMAT" && every=4 # under the sanitizers every fourth node: the same code paths, a quarter of the cost
while read -r name model; do
    checked=$((checked + 1))
    [ $(((checked - 1) % every)) -eq 0 ] || continue
    "$GMAT" check "$TMP/one.mat" "$name" --colormodel "$model" $OPTS > "$TMP/log" 2>&1
    failing=$(awk '$2 == "worst" && / FAIL / && $1 != "albedo" { print $1 }' "$TMP/log")
    grep -q ' worst ' "$TMP/log" || failing="no report"
    [ -z "$failing" ] || fail "$name in $model: $failing
$(cat "$TMP/log")"
done < "$TMP/nodes"
[ "$checked" -eq 48 ] || fail "checked $checked nodes, expected 48 (12 ordered pairs x 2 methods x 2 generators)"
[ $fails -eq 0 ] && echo "interpolate-one sampling: $checked nodes pass chi2, pdf integral and weight"
exit $fails
