!> The descent engine as the step sees it (&engine): a constant thrust along a fixed direction of
!! the lander axes, applied at a fixed point, for 0 <= t < cutoff_time. Its parameters are set once
!! from the input (make_engine); the evaluation asks for the thrust at its time (thrust_at) and for
!! the moment about the mass centre of a force at the engine's point (moment_about).
module landyn_engine
  use landyn_kinds, only: wp
  use landyn_kinematics, only: cross3
  use landyn_config, only: engine_cfg_t
  implicit none
  private

  public :: engine_t, make_engine

  !> The engine's parameters (immutable during a run).
  type :: engine_t
    real(wp) :: thrust = 0.0_wp                           !! thrust magnitude [N]
    real(wp) :: direction(3) = [0.0_wp, 0.0_wp, -1.0_wp]  !! thrust direction, lander frame (normalised) [-]
    real(wp) :: point(3) = 0.0_wp                         !! point of application, lander frame [m]
    real(wp) :: cutoff_time = 0.0_wp                      !! thrust acts for t < cutoff_time [s]
  contains
    procedure :: thrusting => engine_thrusting   !! the engine thrusts at t
    procedure :: thrust_at => engine_thrust_at   !! the thrust at t, lander axes (zero after cutoff)
    procedure :: moment_about => engine_moment_about  !! moment about a point of a force at the engine point
  end type engine_t

contains

  !> The engine of an &engine group.
  pure function make_engine(cfg) result(eng)
    type(engine_cfg_t), intent(in) :: cfg   !! &engine input (resolved, validated) [-]
    type(engine_t) :: eng                   !! the engine [-]
    eng%thrust = cfg%thrust
    eng%direction = cfg%direction
    eng%point = cfg%point
    eng%cutoff_time = cfg%cutoff_time
  end function make_engine

  !> The engine thrusts at t: a positive thrust before the cutoff time.
  elemental logical function engine_thrusting(self, t) result(on)
    class(engine_t), intent(in) :: self   !! engine [-]
    real(wp), intent(in) :: t             !! time [s]
    on = self%thrust > 0.0_wp .and. t < self%cutoff_time
  end function engine_thrusting

  !> The thrust force at t, lander axes: thrust times direction while it thrusts, else zero.
  pure function engine_thrust_at(self, t) result(f)
    class(engine_t), intent(in) :: self   !! engine [-]
    real(wp), intent(in) :: t             !! time [s]
    real(wp) :: f(3)                      !! thrust force, lander axes [N]
    f = 0.0_wp
    if (self%thrusting(t)) f = self%thrust*self%direction
  end function engine_thrust_at

  !> The moment about the point c (the mass centre), lander axes, of a force f acting at the
  !! engine's point of application: (point - c) x f. The step applies it to the deck's thrust and
  !! to a caller's input force (landyn_session), both taken at this point.
  pure function engine_moment_about(self, c, f) result(m)
    class(engine_t), intent(in) :: self   !! engine [-]
    real(wp), intent(in) :: c(3)          !! the point the moment is taken about (the mass centre), lander frame [m]
    real(wp), intent(in) :: f(3)          !! force acting at the engine's point, lander axes [N]
    real(wp) :: m(3)                      !! its moment about c, lander axes [N m]
    m = cross3(self%point - c, f)
  end function engine_moment_about

end module landyn_engine
