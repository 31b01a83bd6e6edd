!> The interface every landing-gear type offers: a gear is a set of struts between the body and
!! one footpad, with its own generalized coordinates, and what the rest of the code needs from it
!! is listed here as deferred bindings. The tripod of the paper (landyn_gear, landyn_tripod_gear)
!! is one extension; a gear type with another strut set is another extension of gear_base_t, not
!! an edit of the tripod (test_gear_types defines a single telescopic strut with a footpad and
!! drives both through this interface).
!!
!! Sign conventions shared by all gear types: gear frame fixed to the body; forces in newtons in
!! the gear frame; strokes in each strut's Table-3 sense; axial forces compression positive.
module landyn_gear_base
  use landyn_kinds, only: wp
  implicit none
  private

  public :: gear_base_t

  !> A landing gear: struts, footpad and their state.
  type, abstract :: gear_base_t
  contains
    procedure(count_iface), deferred :: strut_count
    procedure(count_iface), deferred :: coordinate_count
    procedure(footpad_iface), deferred :: footpad
    procedure(dynamics_iface), deferred :: dynamics
    procedure(integrate_iface), deferred :: integrate
    procedure(per_strut_pair_iface), deferred :: strokes
    procedure(per_strut_iface), deferred :: axial_forces
    procedure(per_strut_iface), deferred :: crush_work
    procedure(body_load_iface), deferred :: body_load
    procedure(energy_iface), deferred :: relative_kinetic_energy
  end type gear_base_t

  abstract interface
    !> A count of the gear type (struts, generalized coordinates).
    pure integer function count_iface(self)
      import :: gear_base_t
      class(gear_base_t), intent(in) :: self      !! gear
    end function count_iface

    !> Footpad joint position and its velocity relative to the body, gear frame.
    pure subroutine footpad_iface(self, pos, vel)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: self      !! gear
      real(wp), intent(out) :: pos(3)             !! position [m]
      real(wp), intent(out) :: vel(3)             !! velocity [m/s]
    end subroutine footpad_iface

    !> Crush logic and accelerations for a footpad force and the uniform field, committed as the
    !! gear's state (buffer forces, modes, the load on the body).
    subroutine dynamics_iface(self, f_foot, f_field, stat, errmsg, dt)
      import :: gear_base_t, wp
      class(gear_base_t), intent(inout) :: self   !! gear
      real(wp), intent(in) :: f_foot(3)           !! ground force on the footpad, gear frame [N]
      real(wp), intent(in) :: f_field(3)          !! uniform field g - a_frame, gear frame [m/s^2]
      integer, intent(out) :: stat                !! STAT_OK on success
      character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
      real(wp), intent(in), optional :: dt        !! coming time step (velocity-level locking) [s]
    end subroutine dynamics_iface

    !> One semi-implicit Euler step of the gear alone (body held fixed) with its constraint
    !! correction, crush history and absorbed work.
    subroutine integrate_iface(self, dt, tol, max_iter, max_drift, stat, errmsg)
      import :: gear_base_t, wp
      class(gear_base_t), intent(inout) :: self   !! gear
      real(wp), intent(in) :: dt                  !! time step [s]
      real(wp), intent(in) :: tol                 !! correction tolerance [m, m/s]
      integer, intent(in) :: max_iter             !! iteration cap of the correction [-]
      real(wp), intent(in) :: max_drift           !! violation before correction that means dt is too large [m]
      integer, intent(out) :: stat                !! STAT_OK on success
      character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    end subroutine integrate_iface

    !> Two per-strut quantities (size strut_count()).
    pure subroutine per_strut_pair_iface(self, s, sd)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: self      !! gear
      real(wp), intent(out) :: s(:)               !! strokes [m]
      real(wp), intent(out) :: sd(:)              !! stroke rates [m/s]
    end subroutine per_strut_pair_iface

    !> One per-strut quantity (size strut_count()).
    pure subroutine per_strut_iface(self, v)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: self      !! gear
      real(wp), intent(out) :: v(:)               !! per strut [N or J]
    end subroutine per_strut_iface

    !> The gear's load on the body in the model (the ground force minus the rate of the legs'
    !! relative momentum) and its moment about the lander origin, gear frame.
    pure subroutine body_load_iface(self, f_body, m_body)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: self      !! gear
      real(wp), intent(out) :: f_body(3)          !! force [N]
      real(wp), intent(out) :: m_body(3)          !! moment [N m]
    end subroutine body_load_iface

    !> Kinetic energy of the leg parts relative to the body.
    pure real(wp) function energy_iface(self)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: self      !! gear
    end function energy_iface
  end interface

end module landyn_gear_base
