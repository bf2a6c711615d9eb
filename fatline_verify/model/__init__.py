"""The model: exact numbers and geometry, the lattice, the option catalogue, a Model and its swarm."""
