// The accuracy cases of the body treatments: one run is one grid level, one method.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fluid/body_methods.hpp"

namespace cosim::bench {

struct FluidRun {
  std::string scene, level, method;
  long cells = 0;
  int steps = 0;
  double seconds = 0, value = 0, reference = 0;
  double check = 0;  // a second figure the case reports (C_L, or F against its momentum balance)
  double error() const { return (value - reference) / reference; }
};

// DFG 2D-1 (Schäfer & Turek 1996), Re 20, steady drag coefficient C_D (reference 5.5795);
// the lift (reference 0.010619) is `check`. The cylinder's centre is (0.2, 0.2) moved by
// `shift` cell widths along x and y (its alignment to the grid).
FluidRun dfg_cylinder(int cells_per_diameter, const fluid::BodyOptions& method, const Eigen::Vector2d& shift = {0, 0});

// Hasimoto (1959) periodic array of spheres, a/L = 0.2, d/h = 0.4 n: the steady Stokes drag
// per sphere of the array at the mean velocity U the run reaches, whose momentum balance is
// F = rho f L^3 (the drive over the whole cell), against Hasimoto's 6 pi mu a U K(c). The
// sphere's centre is `centre` (box [0, 1]^3); `check` is the body's measured force over the
// momentum balance's (one when steady; the staircase's counts the drive on its imposed
// faces, which carry none).
// Stepped at the viscous number nu dt / h^2 with the viscous term's implicit weight theta;
// at most `max_steps` steps (a quick run stops short of the steady state).
struct StokesStepping {
  double viscous_number = 1, theta = 1;
  int max_steps = 20000;
};
FluidRun hasimoto_sphere(int n, const fluid::BodyOptions& method, const Eigen::Vector3d& centre,
                         const StokesStepping& stepping = {});

// How smooth a body's force is in its pose: a sphere (d/h = 8) moved at a steady pace
// through Stokes flow (Re 0.05) in a closed box, one cell in `steps_per_cell` steps along
// (1, 0.37, 0.21), its drag after every step over one cell of travel once the start has
// passed. The drag changes smoothly as the sphere nears a wall; what a least-squares
// quadratic in time does not follow is the method's. Spread: the largest deviation from it,
// jump: the largest change of that deviation from one step to the next, both relative to
// the mean drag.
struct Smoothness {
  double mean_drag = 0, spread = 0, jump = 0;
  int steps = 0;
  double seconds = 0;
};
Smoothness sphere_through_a_cell(const fluid::BodyOptions& method, int steps_per_cell);

// What the time step costs a moving body: a sphere of `cells_per_diameter` cells across (ten
// Cate's d/h is 6) in a closed box of 6.7 x 6.7 x 10.7 diameters (as their tank; 40 x 40 x 64
// cells at d/h 6) towed downwards at constant speed U from rest at Reynolds number U d / nu,
// its drag over the cell of travel that ends 3.3 diameters from the start (a whole cell, over
// which the kernel's ripple as the markers cross the grid averages out: at Re 32 it swings
// the drag by 3 % within a cell), with the fluid's step dt = cells_per_step h / U. Its speed
// rises from rest to U over `rise` d / U (3 x^2 - 2 x^3 in time; 0: at once).
// The viscous number nu dt / h^2 is cells_per_diameter cells_per_step / Re.
struct Towed {
  double cells_per_step = 0, viscous_number = 0, drag = 0, seconds = 0;
  double corrections = 0;  // the immersed boundary's no-slip corrections per step
  int steps = 0;
};
// `stepping`: its theta and pressure update (the step is the case's).
Towed towed_sphere(const fluid::BodyOptions& method, int cells_per_diameter, double cells_per_step, double reynolds,
                   double rise, const fluid::navier_stokes::TimeStepOptions& stepping);

// A sphere driven towards a no-slip wall: a sphere of `cells_per_diameter` cells across in
// a closed cube `box.diameters` wide (by default ten Cate's tank's width, 6.7), moved at
// constant speed U straight down from rest, `box.start_gap` radii above the floor, at
// Reynolds number U d / nu, with fluid steps of nu dt / h^2 = `viscous_number`. Its drag over Stokes's 6 pi mu a U as
// the gap to the floor passes each of `gaps` (in radii, falling), linear between the two steps around it; and at the
// end of every step.
struct WallApproach {
  double cells_per_step = 0, seconds = 0;
  double corrections = 0;  // the immersed boundary's no-slip corrections per step
  int steps = 0;
  std::vector<double> factors;                        // F / (6 pi mu a U) at each gap
  std::vector<double> sampled_gaps, sampled_factors;  // after each step
  fluid::navier_stokes::StageSeconds stages;          // wall seconds per stage, all steps
};
struct WallApproachBox {
  double diameters = 6.7;  // the cube's width
  double start_gap = 3;    // in radii, raised by 0.42 h off the cells' faces
};
WallApproach sphere_approaching_a_wall(const fluid::BodyOptions& method, int cells_per_diameter, double viscous_number,
                                       double reynolds, const std::vector<double>& gaps,
                                       const fluid::navier_stokes::TimeStepOptions& stepping,
                                       const WallApproachBox& box = {});

// The relative error of `run`'s drag against `finest`'s at `gap`: at the two steps of `run`
// around it, each against the finest's drag where that step ended, then linear between them.
// (The drag itself, near 1 / gap, is far from linear across a large step; its error is
// smooth.) A step below where the finest ended counts for nothing.
double error_against(const WallApproach& run, const WallApproach& finest, double gap);

// Brenner's (1961) exact Stokes drag of a sphere moving straight towards a plane no-slip
// wall, over 6 pi mu a U, at a gap of `gap` radii between the sphere and the wall.
double brenner_wall_factor(double gap);

// ten Cate's tank seen from its settling sphere, without the lids: the sphere held in a
// square duct 20/3 diameters wide (100 mm for 15 mm), 5 diameters downstream of a uniform
// inflow U and 11 upstream of the outflow, its walls sliding past at U. The steady drag
// over Stokes's 3 pi mu U d (the side walls' and the Reynolds number's corrections
// together), for comparison with an independent solver on the same geometry
// (openfoam_duct.py).
struct DuctDrag {
  long cells = 0;
  int steps = 0;
  double factor = 0, seconds = 0;
};
DuctDrag sphere_in_sliding_duct(const fluid::BodyOptions& method, int cells_per_diameter, double reynolds);

// Galilean invariance of a moving body: Hasimoto's array driven to about Reynolds number
// `reynolds` (2 a U / nu, the drive from Hasimoto's Stokes drag) with the sphere fixed until
// steady, then the same flow seen from a frame moving at -U (NavierStokes::shift_frame):
// the sphere towed at -U through fluid at rest far off, with fluid steps in which it moves
// `cells_per_step` cells (Crank-Nicolson). The towed sphere's drag over its third and
// fourth cell of travel against the fixed sphere's: they differ only where a moving body's
// discretisation does.
struct MovingFrame {
  double reynolds = 0, cells_per_step = 0, viscous_number = 0, fixed_drag = 0, moving_drag = 0, seconds = 0;
  double error() const { return moving_drag / fixed_drag - 1; }
};
MovingFrame moving_frame(int n, const fluid::BodyOptions& method, double reynolds, double cells_per_step);

}  // namespace cosim::bench
