!> Footpad-ground normal contact laws (paper eqs. 17-18, section 4.1, Tables 4-5).
!!
!! Conventions
!! - delta is the penetration of the footpad into the ground along the local surface normal
!!   (landyn_terrain: delta > 0 inside the ground), delta_dot = d(delta)/dt (> 0 when moving deeper).
!! - normal_force returns the magnitude F_Z >= 0 of the force the ground exerts on the footpad
!!   along the OUTWARD normal n. It is zero for delta <= 0 and never pulls (clamped at 0).
!! - elastic_energy is the energy stored in the conservative (spring) part, E(delta) with
!!   dE/d(delta) = spring_force(delta). dissipation_power = (F_Z - spring_force) * delta_dot is
!!   the power the contact removes from the mechanical system (>= 0 for the base law), so that
!!       integral(F_Z * delta_dot dt) = E(delta) + integral(dissipation_power dt)
!!   (the work done on the ground) closes the energy audit.
!!
!! Adding a law: extend contact_law_t in this module, implement the deferred procedures
!! (pure, allocation-free), and add a `case` to make_contact_law. A law that needs memory
!! (e.g. Hunt-Crossley's impact velocity) should keep it in its own components; create one
!! instance per footpad then.
module landyn_contact
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t, name_len
  implicit none
  private

  public :: contact_law_t, base_contact_t
  public :: base_contact, make_contact_law
  public :: contact_law_names

  !> Names accepted in &contact law, for messages and documentation.
  character(len=*), parameter :: contact_law_names = 'base'

  !> A footpad-ground normal contact law.
  type, abstract :: contact_law_t
    character(len=name_len) :: name = ''  !! law name as given in &contact law [-]
  contains
    procedure(normal_force_i), deferred :: normal_force
    procedure(spring_force_i), deferred :: spring_force
    procedure(elastic_energy_i), deferred :: elastic_energy
    procedure :: dissipation_power
  end type contact_law_t

  abstract interface
    !> Normal force magnitude F_Z >= 0 along the outward surface normal.
    pure function normal_force_i(self, delta, delta_dot) result(f)
      import :: contact_law_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration, > 0 inside the ground [m]
      real(wp), intent(in) :: delta_dot         !! penetration rate, > 0 moving deeper [m/s]
      real(wp) :: f                             !! normal force, >= 0 [N]
    end function normal_force_i

    !> Conservative (spring) part of the normal force, dE/d(delta).
    pure function spring_force_i(self, delta) result(f)
      import :: contact_law_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      real(wp) :: f                             !! spring force [N]
    end function spring_force_i

    !> Energy stored in the spring part at penetration delta (0 for delta <= 0).
    pure function elastic_energy_i(self, delta) result(e)
      import :: contact_law_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      real(wp) :: e                             !! stored elastic energy [J]
    end function elastic_energy_i
  end interface

  !> Base law of the paper (eq. 18): F_Z = K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1),
  !! F_Z = 0 for delta <= 0, clamped at 0 (never pulls).
  type, extends(contact_law_t) :: base_contact_t
    real(wp) :: stiffness = 3.16227766016838e9_wp  !! K_g [N/m^exponent]
    real(wp) :: exponent = 1.5_wp                  !! n [-]
    real(wp) :: damping = 1.0e4_wp                 !! C_g [N s/m]
    real(wp) :: damping_depth = 1.0e-4_wp          !! D1: penetration at which full damping applies [m]; 0: no ramp
  contains
    procedure :: normal_force => base_normal_force
    procedure :: spring_force => base_spring_force
    procedure :: elastic_energy => base_elastic_energy
  end type base_contact_t

contains

  !> Build the law named by cfg%law (case-insensitive) from the &contact input.
  !! stat /= 0 and errmsg set for an unknown name or invalid parameters (law is then unallocated).
  subroutine make_contact_law(cfg, law, stat, errmsg)
    type(contact_cfg_t), intent(in) :: cfg                       !! resolved &contact input
    class(contact_law_t), allocatable, intent(out) :: law        !! the law
    integer, intent(out) :: stat                                 !! 0 on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success

    stat = 0
    errmsg = ''
    select case (lower(trim(adjustl(cfg%law))))
    case ('base')
      if (.not. (cfg%stiffness > 0.0_wp .and. cfg%stiffness <= huge(1.0_wp))) then
        call fail('&contact stiffness must be a finite number > 0')
      else if (.not. (cfg%exponent > 0.0_wp .and. cfg%exponent <= huge(1.0_wp))) then
        call fail('&contact exponent must be a finite number > 0')
      else if (.not. (cfg%damping >= 0.0_wp .and. cfg%damping <= huge(1.0_wp))) then
        call fail('&contact damping must be a finite number >= 0')
      else if (.not. (cfg%damping_depth >= 0.0_wp .and. cfg%damping_depth <= huge(1.0_wp))) then
        call fail('&contact damping_depth must be a finite number >= 0')
      else
        allocate (law, source=base_contact(cfg%stiffness, cfg%exponent, cfg%damping, cfg%damping_depth))
      end if
    case default
      call fail("&contact law = '"//trim(adjustl(cfg%law))//"' is not known; known laws: "//contact_law_names)
    end select

  contains

    subroutine fail(msg)
      character(len=*), intent(in) :: msg  !! error message
      stat = 1
      errmsg = msg
    end subroutine fail

  end subroutine make_contact_law

  !> Base law with the given parameters.
  pure function base_contact(stiffness, exponent, damping, damping_depth) result(law)
    real(wp), intent(in) :: stiffness      !! K_g [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! C_g [N s/m]
    real(wp), intent(in) :: damping_depth  !! D1 [m]
    type(base_contact_t) :: law            !! the law
    law%name = 'base'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%damping_depth = damping_depth
  end function base_contact

  pure function base_normal_force(self, delta, delta_dot) result(f)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 inside the ground [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate, > 0 moving deeper [m/s]
    real(wp) :: f                              !! normal force, >= 0 [N]
    real(wp) :: kappa

    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    if (delta < self%damping_depth) then
      kappa = delta/self%damping_depth
    else
      kappa = 1.0_wp
    end if
    f = max(0.0_wp, self%stiffness*delta**self%exponent + kappa*self%damping*delta_dot)
  end function base_normal_force

  pure function base_spring_force(self, delta) result(f)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    real(wp) :: f                              !! K delta^n, 0 for delta <= 0 [N]
    if (delta > 0.0_wp) then
      f = self%stiffness*delta**self%exponent
    else
      f = 0.0_wp
    end if
  end function base_spring_force

  pure function base_elastic_energy(self, delta) result(e)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    real(wp) :: e                              !! K delta^(n+1)/(n+1), 0 for delta <= 0 [J]
    if (delta > 0.0_wp) then
      e = self%stiffness*delta**(self%exponent + 1.0_wp)/(self%exponent + 1.0_wp)
    else
      e = 0.0_wp
    end if
  end function base_elastic_energy

  !> Power removed from the mechanical system by the contact: (F_Z - spring_force) * delta_dot.
  !! Includes the spring energy lost when the clamp F_Z >= 0 is active during fast unloading.
  pure function dissipation_power(self, delta, delta_dot) result(p)
    class(contact_law_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta             !! penetration [m]
    real(wp), intent(in) :: delta_dot         !! penetration rate [m/s]
    real(wp) :: p                             !! dissipated power [W]
    p = (self%normal_force(delta, delta_dot) - self%spring_force(delta))*delta_dot
  end function dissipation_power

  pure function lower(s) result(t)
    character(len=*), intent(in) :: s  !! text
    character(len=len(s)) :: t         !! s in lower case
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
    end do
  end function lower

end module landyn_contact
