# The shared scenes each benchmark runs on, in one place (sourced by bench.sh, skips.sh and
# gpu-run.sh, so the GPU column measures what the llvmpipe page does). Paths relative to SCENES_DIR.
BENCH_SCENES=(CornellBox/cornellBox.gltf FlightHelmet/FlightHelmet.gltf 2CylinderEngine/2CylinderEngine.gltf
              Lantern/Lantern.gltf ReciprocatingSaw/ReciprocatingSaw.gltf ShaderBall/shader_ball.gltf)
SKIPS_SCENES=(CornellBox/cornellBox.gltf 2CylinderEngine/2CylinderEngine.gltf
              ReciprocatingSaw/ReciprocatingSaw.gltf Lantern/Lantern.gltf FlightHelmet/FlightHelmet.gltf)
