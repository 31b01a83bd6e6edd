!> The footpad-ground normal contact law interface (paper eqs. 1, 17-18, section 4.1, Tables 4-5):
!! the abstract `contact_law_t`, the contact history `contact_state_t`, the Hertz spring part
!! shared by most laws, and the parameter checks the laws share. The laws are in
!! landyn_contact_<law>.f90, listed in the registry landyn_contact.
!!
!! Conventions
!! - delta is the penetration of the footpad into the ground along the local surface normal
!!   (landyn_terrain: delta > 0 inside the ground), delta_dot = d(delta)/dt (> 0 when moving deeper).
!! - normal_force returns the magnitude F_Z >= 0 of the force the ground exerts on the footpad
!!   along the OUTWARD normal n. It is zero for delta <= 0 and never pulls (every law is clamped
!!   at 0, also where the printed formula would pull).
!! - elastic_energy is the energy stored in the conservative (spring) part, E(delta) with
!!   dE/d(delta) = spring_force(delta). dissipation_power = F_Z delta_dot - dE/dt is the power the
!!   contact removes from the mechanical system, so that
!!       integral(F_Z * delta_dot dt) = E(delta) + integral(dissipation_power dt)
!!   (the work done on the ground) closes the energy audit. For laws whose spring part depends on
!!   delta only, dissipation_power = (F_Z - spring_force) * delta_dot.
!!
!! History. Hunt-Crossley needs the impact velocity of the current contact and the regolith law
!! the deepest sinkage reached: such laws set `has_history` and read a `contact_state_t`, the
!! contact history of one footpad, passed to every evaluation. The laws themselves are immutable
!! parameter objects (one instance serves all footpads): the state belongs to the model state, and
!! `advance_contact_state(state, delta, delta_dot)` moves it on, called by the integrator only when
!! it commits a step; laws without history ignore the state, so their cost is unchanged. Every
!! evaluation is a pure function of (delta, delta_dot, state) and the law. Without a state the
!! history laws evaluate as on a fresh contact (no recorded impact, no deeper crater).
!!
!! Building from the input. Every law module has a builder `build(b)`, b a contact_build_t
!! holding the &contact input, the message prefix and the messages so far. It starts with
!! `b%wanted(depth_needed)` (or `b%hertz_wanted(depth_needed, damped)` for a K delta^n spring),
!! which appends the law-dependent check (the damping_depth rule) and is .false. with
!! b%check_only; otherwise the builder appends the range checks of its parameters and allocates
!! b%law (the registry discards it when a check failed). With b%check_only that is the input
!! validation (check_contact_law_input), so deck validation and factory share one rule.
module landyn_contact_law
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t, name_len
  use landyn_law_checks, only: law_build_t, positive
  implicit none
  private

  public :: contact_law_t, contact_state_t, contact_build_t, hertz_spring_t, hertz_damper_t, damped_hertz_t
  public :: advance_contact_state

  !> Contact history of one footpad (used by laws with has_history only).
  type :: contact_state_t
    logical :: touching = .false.     !! in contact (delta > 0) at the last update [-]
    real(wp) :: v_impact = 0.0_wp     !! penetration rate at the first step of the current contact [m/s]
    real(wp) :: delta_max = 0.0_wp    !! deepest penetration reached so far; kept after lift-off [m]
  end type contact_state_t

  !> A footpad-ground normal contact law: immutable parameters (the history is a contact_state_t).
  type, abstract :: contact_law_t
    character(len=name_len) :: name = ''  !! law name as given in &contact law [-]
    logical :: has_history = .false.      !! the law reads a contact_state_t: advance it once per step [-]
  contains
    procedure(normal_force_i), deferred :: normal_force      !! normal force F_Z >= 0 [N]
    procedure(spring_force_i), deferred :: spring_force      !! conservative part of F_Z, dE/d(delta) [N]
    procedure(elastic_energy_i), deferred :: elastic_energy  !! energy E(delta) stored in the spring part [J]
    procedure :: dissipation_power                           !! power the contact removes, (F_Z - spring) delta_dot [W]
    procedure :: tangent                                     !! dF_Z/d(delta), dF_Z/d(delta_dot) [N/m, N s/m]
  end type contact_law_t

  abstract interface
    !> Normal force magnitude F_Z >= 0 along the outward surface normal.
    pure function normal_force_i(self, delta, delta_dot, state) result(f)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration, > 0 inside the ground [m]
      real(wp), intent(in) :: delta_dot         !! penetration rate, > 0 moving deeper [m/s]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: f                             !! normal force, >= 0 [N]
    end function normal_force_i

    !> Conservative (spring) part of the normal force, dE/d(delta).
    pure function spring_force_i(self, delta, state) result(f)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: f                             !! spring force [N]
    end function spring_force_i

    !> Energy stored in the spring part at penetration delta (0 for delta <= 0).
    pure function elastic_energy_i(self, delta, state) result(e)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: e                             !! stored elastic energy [J]
    end function elastic_energy_i
  end interface

  !> What a contact law builder works on: the &contact input and the law it builds, besides the
  !! group, prefix, messages and check_only of law_build_t.
  type, extends(law_build_t) :: contact_build_t
    type(contact_cfg_t) :: cfg                    !! resolved &contact input
    class(contact_law_t), allocatable :: law      !! the law built (also when a check failed)
  contains
    procedure :: wanted => contact_wanted               !! the damping_depth rule; build the law?
    procedure :: hertz_wanted => contact_hertz_wanted   !! the same, then the spring and damper checks
  end type contact_build_t

  !> Laws whose spring part is K delta^n (all but regolith).
  type, abstract, extends(contact_law_t) :: hertz_spring_t
    real(wp) :: stiffness = 3.16227766016838e9_wp  !! K [N/m^exponent]
    real(wp) :: exponent = 1.5_wp                  !! n [-]
  contains
    procedure :: spring_force => hertz_spring_force      !! K delta^n [N]
    procedure :: elastic_energy => hertz_elastic_energy  !! K delta^(n+1)/(n+1) [J]
    procedure :: damped_force                            !! K delta^n + c delta_dot clamped at 0 [N]
  end type hertz_spring_t

  !> Hertz spring and a linear damping coefficient (the laws with a `damping` input).
  type, abstract, extends(hertz_spring_t) :: hertz_damper_t
    real(wp) :: damping = 1.0e4_wp                 !! linear damping coefficient (C, D, D1) [N s/m]
  end type hertz_damper_t

  !> Hertz spring and a linear damper whose coefficient may depend on the penetration:
  !! F_Z = max(0, K delta^n + c(delta) delta_dot) inside the ground (delta > 0), 0 outside.
  !! A law of this kind only implements damping_coefficient.
  type, abstract, extends(hertz_damper_t) :: damped_hertz_t
  contains
    procedure(damping_coefficient_i), deferred :: damping_coefficient  !! c(delta) [N s/m]
    procedure :: normal_force => damped_hertz_normal_force           !! max(0, K delta^n + c(delta) delta_dot) [N]
  end type damped_hertz_t

  abstract interface
    !> The damping coefficient c(delta) at the penetration delta > 0.
    pure function damping_coefficient_i(self, delta) result(c)
      import :: damped_hertz_t, wp
      class(damped_hertz_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta              !! penetration, > 0 [m]
      real(wp) :: c                              !! damping coefficient [N s/m]
    end function damping_coefficient_i
  end interface

contains

  ! ---------------------------------------------------------------- common procedures

  !> Advances one footpad's contact history to the penetration delta (laws with has_history; done
  !! before the forces are evaluated at that penetration, and committed with the step).
  !! A contact starts at the first advance with delta > 0: its penetration rate is the impact
  !! velocity. delta <= 0 ends the contact; the deepest penetration is kept (a crater stays).
  pure subroutine advance_contact_state(state, delta, delta_dot)
    type(contact_state_t), intent(inout) :: state  !! contact history of one footpad
    real(wp), intent(in) :: delta                  !! penetration [m]
    real(wp), intent(in) :: delta_dot              !! penetration rate [m/s]
    if (delta > 0.0_wp) then
      if (.not. state%touching) then
        state%touching = .true.
        state%v_impact = max(delta_dot, 0.0_wp)
      end if
      state%delta_max = max(state%delta_max, delta)
    else
      state%touching = .false.
    end if
  end subroutine advance_contact_state

  !> Power removed from the mechanical system by the contact: (F_Z - spring_force) * delta_dot.
  !! Includes the spring energy lost when the clamp F_Z >= 0 is active during fast unloading.
  pure function dissipation_power(self, delta, delta_dot, state) result(p)
    class(contact_law_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta             !! penetration [m]
    real(wp), intent(in) :: delta_dot         !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: p                             !! dissipated power [W]
    p = (self%normal_force(delta, delta_dot, state) - self%spring_force(delta, state))*delta_dot
  end function dissipation_power

  !> The tangent of the normal force at (delta, delta_dot): k = dF_Z/d(delta), c = dF_Z/d(delta_dot),
  !! by differences of normal_force with the same contact history (every law; a law may override it
  !! with its analytic derivatives). k is the one-sided derivative in the direction the penetration
  !! moves (delta_dot >= 0: deeper), second order, step 1e-6 of the penetration (at least 1e-10 m),
  !! so that a law whose branch changes there (regolith at its deepest sinkage) gives the branch the
  !! step enters; c is a central difference, step 1e-6 of the rate (at least 1e-6 m/s). Outside
  !! the ground (delta <= 0) both are 0. Used by the linearly implicit footpad contact
  !! (landyn_scheme_imex).
  pure subroutine tangent(self, delta, delta_dot, k, c, state)
    class(contact_law_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta             !! penetration [m]
    real(wp), intent(in) :: delta_dot         !! penetration rate [m/s]
    real(wp), intent(out) :: k                !! dF_Z/d(delta) [N/m]
    real(wp), intent(out) :: c                !! dF_Z/d(delta_dot) [N s/m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: hd, hv
    k = 0.0_wp
    c = 0.0_wp
    if (delta <= 0.0_wp) return
    hd = max(1.0e-6_wp*delta, 1.0e-10_wp)
    if (delta_dot < 0.0_wp) hd = -min(hd, 0.25_wp*delta)   ! backward: stay inside the ground
    k = (-3.0_wp*self%normal_force(delta, delta_dot, state) + 4.0_wp*self%normal_force(delta + hd, delta_dot, state) &
         - self%normal_force(delta + 2.0_wp*hd, delta_dot, state))/(2.0_wp*hd)
    hv = max(1.0e-6_wp*abs(delta_dot), 1.0e-6_wp)
    c = (self%normal_force(delta, delta_dot + hv, state) - self%normal_force(delta, delta_dot - hv, state))/(2.0_wp*hv)
  end subroutine tangent

  !> The Hertz spring force K delta^n (0 outside the ground).
  pure function hertz_spring_force(self, delta, state) result(f)
    class(hertz_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! K delta^n, 0 for delta <= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta > 0.0_wp) then
      f = self%stiffness*delta**self%exponent
    else
      f = 0.0_wp
    end if
  end function hertz_spring_force

  !> The energy stored in the Hertz spring, K delta^(n+1)/(n+1) (0 outside the ground).
  pure function hertz_elastic_energy(self, delta, state) result(e)
    class(hertz_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: e                              !! K delta^(n+1)/(n+1), 0 for delta <= 0 [J]
    if (present(state)) e = 0.0_wp   ! the law has no history
    if (delta > 0.0_wp) then
      e = self%stiffness*delta**(self%exponent + 1.0_wp)/(self%exponent + 1.0_wp)
    else
      e = 0.0_wp
    end if
  end function hertz_elastic_energy

  !> K delta^n + c delta_dot clamped at 0 (the damped Hertz laws; delta > 0).
  pure function damped_force(self, delta, c, delta_dot) result(f)
    class(hertz_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 [m]
    real(wp), intent(in) :: c                  !! effective damping coefficient [N s/m]
    real(wp), intent(in) :: delta_dot          !! penetration rate [m/s]
    real(wp) :: f                              !! normal force, >= 0 [N]
    f = max(0.0_wp, self%stiffness*delta**self%exponent + c*delta_dot)
  end function damped_force

  !> Normal force of a damped Hertz law: max(0, K delta^n + c(delta) delta_dot) inside the ground, 0 outside.
  pure function damped_hertz_normal_force(self, delta, delta_dot, state) result(f)
    class(damped_hertz_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 inside the ground [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate, > 0 moving deeper [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by these laws)
    real(wp) :: f                              !! normal force, >= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta <= 0.0_wp) then
      f = 0.0_wp
    else
      f = self%damped_force(delta, self%damping_coefficient(delta), delta_dot)
    end if
  end function damped_hertz_normal_force

  ! ---------------------------------------------------------------- checks of the &contact input

  !> The start of every builder: the law's damping_depth rule (> 0 where the law needs a ramp or
  !! band, depth_needed; otherwise >= 0: base reads 0 as no ramp, the other laws ignore it).
  !! .true. when the law is to be built (not b%check_only): the builder then adds the range checks
  !! of its parameters and allocates b%law.
  function contact_wanted(b, depth_needed) result(go)
    class(contact_build_t), intent(inout) :: b  !! the build (input and messages)
    logical, intent(in) :: depth_needed         !! the law needs damping_depth > 0 [-]
    logical :: go                               !! build the law [-]
    if (depth_needed) then
      call b%require_positive('damping_depth', b%cfg%damping_depth, 'm')
    else
      call b%require_nonnegative('damping_depth', b%cfg%damping_depth, 'm')
    end if
    go = .not. b%check_only
  end function contact_wanted

  !> b%wanted(depth_needed) for a law with a K delta^n spring; when it is to be built, also the
  !! range checks of the spring (stiffness, exponent) and, if damped, of the damping coefficient.
  function contact_hertz_wanted(b, depth_needed, damped) result(go)
    class(contact_build_t), intent(inout) :: b  !! the build (input and messages)
    logical, intent(in) :: depth_needed         !! the law needs damping_depth > 0 [-]
    logical, intent(in) :: damped               !! the law reads the damping coefficient [-]
    logical :: go                               !! build the law [-]
    go = b%wanted(depth_needed)
    if (.not. go) return
    call b%require(positive(b%cfg%stiffness), 'stiffness', b%cfg%stiffness, 'N/m^n', &
                   'stiffness > 0')
    call b%require_positive('exponent', b%cfg%exponent, '')
    if (damped) call b%require_nonnegative('damping', b%cfg%damping, 'N s/m')
  end function contact_hertz_wanted

end module landyn_contact_law
