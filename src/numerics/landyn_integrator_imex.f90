!> Error-controlled variable-step integration with the footpads' normal contact forces linearly
!! implicit (&simulation integrator = 'imex', opt-in; docs/theory.md, "Stiff candidate: linearly
!! implicit footpad contact"). An extension of landyn_integrator_adaptive: its step-size control,
!! event location, retries and output cuts, with two parts replaced. The step is
!! landyn_scheme_imex's instead of the leapfrog: implicit Euler in each footpad's penetration, so
!! that the stiff footpad-soil oscillation is damped rather than resolved. The local error estimate
!! is the adaptive one's (second divided difference of the accelerations, or the first-order one
!! after an event) with the part of the acceleration change that the footpads' normal-force change
!! explains through their unit responses removed: the stiff footpad-normal mode is the implicit
!! scheme's, not the error control's. The unit responses are taken in the field each evaluation
!! was made in and for its step (sim_eval_t%acc_field, alpha_field, dt).
module landyn_integrator_imex
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, max_gears, max_gear_q
  use landyn_config, only: landyn_input_t
  use landyn_status, only: status_t
  use landyn_sim_core, only: sim_t, sim_result_t
  use landyn_integrator_adaptive, only: adaptive_integrator_t, weighted_max
  use landyn_integrator, only: integrator_build_t
  use landyn_scheme_imex, only: imex_advance, imex_responses, imex_response_t
  implicit none
  private

  public :: imex_integrator_t, build

  !> The imex integrator: the adaptive one's state and the footpads' responses at the current state.
  type, extends(adaptive_integrator_t) :: imex_integrator_t
    type(imex_response_t) :: rsp           !! the footpads' responses at the current state
  contains
    procedure :: start => imex_start                !! the adaptive start, named 'imex' in the result
    procedure :: advance => imex_step_advance       !! the responses at t, then landyn_scheme_imex's step
    procedure :: local_error => stiff_free_error    !! the estimate without the footpads' normal-force part
  end type imex_integrator_t

contains

  !> The registry's builder of 'imex' (landyn_integrators).
  subroutine build(b)
    type(integrator_build_t), intent(inout) :: b   !! the build
    allocate (imex_integrator_t :: b%integ)
  end subroutine build

  !> The adaptive integrator's start; the result names this integrator.
  subroutine imex_start(self, sim, inp, res, st)
    class(imex_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                !! simulation at t = 0
    type(landyn_input_t), intent(in) :: inp          !! resolved, validated input (the integrator's settings)
    type(sim_result_t), intent(inout) :: res         !! result
    type(status_t), intent(out) :: st                !! STAT_OK, or the evaluation's failure [-]
    call self%adaptive_integrator_t%start(sim, inp, res, st)
    res%integrator = 'imex'
  end subroutine imex_start

  !> The step h from the current state: the footpads' unit responses at its evaluation, then the
  !! leapfrog with the normal contact forces linearly implicit.
  subroutine imex_step_advance(self, sim, h, st)
    class(imex_integrator_t), intent(inout) :: self  !! integrator (responses kept for the error estimate)
    type(sim_t), intent(inout) :: sim                !! simulation, advanced by h
    real(wp), intent(in) :: h                        !! step [s]
    type(status_t), intent(out) :: st                !! STAT_OK, or the step's failure with its context [-]
    call imex_responses(sim, self%evs(self%i_cur), self%rsp, st)
    if (st%ok()) call imex_advance(sim, self%evs(self%i_cur), self%rsp, h, self%kick(h), st)
  end subroutine imex_step_advance

  !> The local error of the step h just tried over the tolerance: the adaptive integrator's estimate
  !! (h^3/24 |a''| from the second divided difference of the accelerations of the last three
  !! evaluations; h/2 |a(t+h) - a(t)| right after an event) of the accelerations less their part
  !! explained by the footpads' normal forces through the unit responses at t (for every footpad
  !! with a response: in contact and its decisions unchanged), weighted as landyn_integrator_adaptive.
  function stiff_free_error(self, sim, h) result(err)
    class(imex_integrator_t), intent(in) :: self  !! integrator (records, responses)
    type(sim_t), intent(in) :: sim                !! simulation (counts, size)
    real(wp), intent(in) :: h                     !! step tried [s]
    real(wp) :: err                               !! error / tolerance [-]
    real(wp) :: d_acc(3), d_alpha(3), d_qdd(max_gear_q, max_gears), dfn, c0, c1
    integer :: i, ng, nq
    ng = sim%model%par%n_gears
    associate (ep => self%evs(self%i_prev), e0 => self%evs(self%i_cur), e1 => self%evs(self%i_new), r => self%rsp)
      if (self%smooth) then
        c1 = 1.0_wp/h
        c0 = 1.0_wp/self%h_last
        d_acc = (e1%acc - e0%acc)*c1 - (e0%acc - ep%acc)*c0
        d_alpha = (e1%alpha - e0%alpha)*c1 - (e0%alpha - ep%alpha)*c0
        d_qdd(:, 1:ng) = (e1%qdd(:, 1:ng) - e0%qdd(:, 1:ng))*c1 - (e0%qdd(:, 1:ng) - ep%qdd(:, 1:ng))*c0
      else
        d_acc = e1%acc - e0%acc
        d_alpha = e1%alpha - e0%alpha
        d_qdd(:, 1:ng) = e1%qdd(:, 1:ng) - e0%qdd(:, 1:ng)
      end if
      do i = 1, ng
        if (.not. r%on(i)) cycle
        if (self%smooth) then
          dfn = (e1%fn(i) - e0%fn(i))*c1 - (e0%fn(i) - ep%fn(i))*c0
        else
          dfn = e1%fn(i) - e0%fn(i)
        end if
        nq = sim%model%par%n_q(i)
        d_acc = d_acc - dfn*r%acc_u(:, i)
        d_alpha = d_alpha - dfn*r%alpha_u(:, i)
        d_qdd(1:nq, i) = d_qdd(1:nq, i) - dfn*r%qdd_u(1:nq, i)
      end do
      err = weighted_max(d_acc, d_alpha, d_qdd(:, 1:ng), e0%q_weight, sim%par%l_char, ng)/self%tol
      if (self%smooth) then
        err = err*h**3/24.0_wp*2.0_wp/(h + self%h_last)
      else
        err = err*0.5_wp*h
      end if
    end associate
    if (.not. ieee_is_finite(err)) err = huge(1.0_wp)
  end function stiff_free_error

end module landyn_integrator_imex
