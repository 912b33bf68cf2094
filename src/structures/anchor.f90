!> The anchor bar (doc/theory.md, Anchors): elongation e = g . u_e with g = (-d, d) for a
!> node-to-node bar (d the unit vector from node 1 to node 2) and g = -d for a fixed-end
!> bar (d from the node to the fixed point); force of one anchor N = (EA/L)(e - e0 - e_p),
!> returned to the tension or compression limit (elastic-perfectly plastic, the plastic
!> elongation grows); nodal forces per unit out-of-plane length N t / L_s g (t the model's
!> thickness, L_s the spacing) and stiffness (dN/de) t / L_s g g^T.
module pecplas_structures_anchor
   use pecplas_base_kinds, only: wp
   use pecplas_model_anchors, only: anchor_set_t, ANCHOR_FIXED_END
   use pecplas_structures_anchor_state, only: anchor_set_state_t
   implicit none (type, external)
   private

   public :: bar_nodes, bar_vector, bar_elongation, bar_update

contains

   !> Number of nodes of the set's bars (1 fixed-end, 2 node-to-node).
   pure integer function bar_nodes(set) result(n)
      type(anchor_set_t), intent(in) :: set
      n = merge(1, 2, set%kind == ANCHOR_FIXED_END)
   end function bar_nodes

   !> g of bar i (2 nodes' x, y): e = g . u_e.
   pure function bar_vector(set, i) result(g)
      type(anchor_set_t), intent(in) :: set
      integer, intent(in) :: i
      real(wp) :: g(2*bar_nodes(set))
      g(1:2) = -set%direction(:, i)
      if (set%kind /= ANCHOR_FIXED_END) g(3:4) = set%direction(:, i)
   end function bar_vector

   !> Elongation of bar i under the nodal displacements u(2, nnode).
   pure real(wp) function bar_elongation(set, i, u) result(e)
      type(anchor_set_t), intent(in) :: set
      integer, intent(in) :: i
      real(wp), intent(in) :: u(:, :)
      real(wp) :: g(2*bar_nodes(set))
      g = bar_vector(set, i)
      e = dot_product(g(1:2), u(:, set%conn(1, i)))
      if (set%kind /= ANCHOR_FIXED_END) e = e + dot_product(g(3:4), u(:, set%conn(2, i)))
   end function bar_elongation

   !> Trial force, plastic elongation and tangent of bar i at elongation e, from the
   !> converged state (a prestressing set: the prestress, no stiffness).
   pure subroutine bar_update(set, st, i, e)
      type(anchor_set_t), intent(in) :: set
      type(anchor_set_state_t), intent(inout) :: st
      integer, intent(in) :: i
      real(wp), intent(in) :: e
      real(wp) :: k, trial
      st%plastic_trial(i) = st%plastic(i)
      if (st%prestressing) then
         st%force_trial(i) = st%prestress
         st%tangent(i) = 0.0_wp
         return
      end if
      k = set%ea/set%length(i)
      trial = k*(e - st%e0(i) - st%plastic(i))
      if (trial > set%tension_limit) then
         st%force_trial(i) = set%tension_limit
         st%plastic_trial(i) = e - st%e0(i) - set%tension_limit/k
         st%tangent(i) = 0.0_wp
      else if (trial < -set%compression_limit) then
         st%force_trial(i) = -set%compression_limit
         st%plastic_trial(i) = e - st%e0(i) + set%compression_limit/k
         st%tangent(i) = 0.0_wp
      else
         st%force_trial(i) = trial
         st%tangent(i) = k
      end if
   end subroutine bar_update

end module pecplas_structures_anchor
