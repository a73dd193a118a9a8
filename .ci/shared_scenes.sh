# Sourced by the page scripts that run every shared scene (.ci/temporal.sh, .ci/objective.sh,
# .ci/layers.sh, .ci/engines.sh): SCENE_ARGS, one --scene FILE for each, from SCENES (the shared scenes' folder).
SCENE_LIST=(CornellBox/cornellBox.gltf ShaderBall/shader_ball.gltf SciFiHelmet/SciFiHelmet.gltf FlightHelmet/FlightHelmet.gltf
            Lantern/Lantern.gltf ReciprocatingSaw/ReciprocatingSaw.gltf 2CylinderEngine/2CylinderEngine.gltf
            AntiqueCamera/AntiqueCamera.gltf)
SCENE_ARGS=()
for s in "${SCENE_LIST[@]}"; do SCENE_ARGS+=(--scene "$SCENES/$s"); done
