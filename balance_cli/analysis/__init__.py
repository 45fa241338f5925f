"""Analyses of one engine, all from its one kinematic state and one harmonic engine: shaking
forces and moments, firing, counterweights and balancer shafts, torques (inertia, gas, crank
pins, guide forces, steadiness), each cylinder's torque, and the marine figures."""
