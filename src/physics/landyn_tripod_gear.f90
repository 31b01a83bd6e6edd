!> The paper's tripod gear (landyn_gear: a primary strut with the footpad and two secondaries) as
!! an extension of gear_base_t: each binding is the tripod's own procedure. The simulation still
!! holds its gears as type(gear_t) (static calls in the inner loop); this type is the tripod seen
!! through the gear-type interface.
module landyn_tripod_gear
  use landyn_kinds, only: wp
  use landyn_gear_base, only: gear_base_t
  use landyn_gear, only: gear_t, gear_footpad, gear_dynamics, gear_integrate, gear_strokes, gear_axial_forces, &
                         gear_crush_work, gear_body_load, gear_relative_kinetic_energy, gear_strut_lengths, gear_rates, &
                         n_struts
  implicit none
  private

  public :: tripod_gear_t

  !> The tripod gear behind the gear-type interface.
  type, extends(gear_base_t) :: tripod_gear_t
    type(gear_t) :: gear                            !! the tripod (landyn_gear)
  contains
    procedure :: strut_count => tripod_strut_count
    procedure :: coordinate_count => tripod_coordinate_count
    procedure :: footpad => tripod_footpad
    procedure :: dynamics => tripod_dynamics
    procedure :: integrate => tripod_integrate
    procedure :: strokes => tripod_strokes
    procedure :: axial_forces => tripod_axial_forces
    procedure :: crush_work => tripod_crush_work
    procedure :: body_load => tripod_body_load
    procedure :: relative_kinetic_energy => tripod_kinetic_energy
  end type tripod_gear_t

contains

  !> Three struts.
  pure integer function tripod_strut_count(self) result(n)
    class(tripod_gear_t), intent(in) :: self        !! gear
    n = size(gear_strut_lengths(self%gear))
  end function tripod_strut_count

  !> Nine generalized coordinates.
  pure integer function tripod_coordinate_count(self) result(n)
    class(tripod_gear_t), intent(in) :: self        !! gear
    n = size(gear_rates(self%gear))
  end function tripod_coordinate_count

  !> Footpad position and velocity, gear frame (gear_footpad).
  pure subroutine tripod_footpad(self, pos, vel)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: pos(3)                 !! [m]
    real(wp), intent(out) :: vel(3)                 !! [m/s]
    call gear_footpad(self%gear, pos, vel)
  end subroutine tripod_footpad

  !> gear_dynamics.
  subroutine tripod_dynamics(self, f_foot, f_field, stat, errmsg, dt)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: f_foot(3)               !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)              !! uniform field, gear frame [m/s^2]
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    real(wp), intent(in), optional :: dt            !! coming time step [s]
    call gear_dynamics(self%gear, f_foot, f_field, stat, errmsg, dt)
  end subroutine tripod_dynamics

  !> gear_integrate with the gear's own velocity projection (body held fixed).
  subroutine tripod_integrate(self, dt, tol, max_iter, max_drift, stat, errmsg)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: dt                      !! time step [s]
    real(wp), intent(in) :: tol                     !! correction tolerance [m, m/s]
    integer, intent(in) :: max_iter                 !! iteration cap [-]
    real(wp), intent(in) :: max_drift               !! largest violation before correction [m]
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    call gear_integrate(self%gear, dt, tol, max_iter, max_drift, stat, errmsg, velocity=.true.)
  end subroutine tripod_integrate

  !> Strokes and stroke rates (gear_strokes).
  pure subroutine tripod_strokes(self, s, sd)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: s(:)                   !! strokes [m]
    real(wp), intent(out) :: sd(:)                  !! stroke rates [m/s]
    real(wp) :: s3(n_struts), sd3(n_struts)
    call gear_strokes(self%gear, s3, sd3)
    s = s3
    sd = sd3
  end subroutine tripod_strokes

  !> Axial buffer forces.
  pure subroutine tripod_axial_forces(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [N]
    v = gear_axial_forces(self%gear)
  end subroutine tripod_axial_forces

  !> Energy absorbed by each buffer.
  pure subroutine tripod_crush_work(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [J]
    v = gear_crush_work(self%gear)
  end subroutine tripod_crush_work

  !> The load on the body (gear_body_load).
  pure subroutine tripod_body_load(self, f_body, m_body)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: f_body(3)              !! [N]
    real(wp), intent(out) :: m_body(3)              !! [N m]
    call gear_body_load(self%gear, f_body, m_body)
  end subroutine tripod_body_load

  !> Relative kinetic energy of the legs.
  pure real(wp) function tripod_kinetic_energy(self) result(t)
    class(tripod_gear_t), intent(in) :: self        !! gear
    t = gear_relative_kinetic_energy(self%gear)
  end function tripod_kinetic_energy

end module landyn_tripod_gear
