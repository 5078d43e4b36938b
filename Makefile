# make run   - install what is missing, then run the main job (the velocity-amplifier study) and say where
#              its report is
# make test  - install what is missing, then run the test suite
VENV := .venv
BIN := $(VENV)/bin
export OMPI_ALLOW_RUN_AS_ROOT := 1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM := 1
export OMPI_MCA_rmaps_base_oversubscribe := 1

.PHONY: install run test verify bench clean parts-pictures
install:
	@bash scripts/install.sh

run: install
	$(BIN)/shockfem study amplifier --out results/amplifier

test: install
	$(BIN)/python -m pytest -q -n 2 --durations=20 tests

verify: install
	$(BIN)/shockfem verify --json results/verify.json

bench: install
	$(BIN)/shockfem bench --json results/bench.json

clean:
	rm -rf results meshes/*.msh meshes/*.regions.json

# Pictures of the catalogue of parts for docs/parts.md (axisymmetric and 3D tetrahedra).
parts-pictures: install
	mkdir -p docs/parts
	for f in studies/gallery/*.toml; do n=$$(basename $$f .toml); \
	  $(VENV)/bin/shockfem mesh $$f --out results/gallery/$$n.xdmf --png docs/parts/$$n.png && \
	  $(VENV)/bin/shockfem mesh $$f --set 'scene.kinematics="3d"' --set 'scene.element="tet"' \
	    --out results/gallery/$${n}_3d.xdmf --png docs/parts/$${n}_3d.png || exit 1; done
