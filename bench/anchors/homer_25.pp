<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="homer.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-0.003504" y="0.500000" z="-0.042462" active="1" name="head_top"/>
 <point x="0.003259" y="0.317782" z="0.100677" active="1" name="nose_tip"/>
 <point x="0.008407" y="0.169387" z="0.089321" active="1" name="chin"/>
 <point x="0.104578" y="0.304319" z="-0.046940" active="1" name="left_ear"/>
 <point x="-0.102553" y="0.304134" z="-0.048861" active="1" name="right_ear"/>
 <point x="0.125525" y="0.142102" z="-0.038576" active="1" name="left_shoulder"/>
 <point x="-0.125687" y="0.141720" z="-0.041617" active="1" name="right_shoulder"/>
 <point x="0.229364" y="0.044013" z="-0.039303" active="1" name="left_elbow"/>
 <point x="-0.224852" y="0.040088" z="-0.043257" active="1" name="right_elbow"/>
 <point x="0.255259" y="0.094910" z="0.079477" active="1" name="left_wrist"/>
 <point x="-0.255855" y="0.092386" z="0.073235" active="1" name="right_wrist"/>
 <point x="0.221321" y="0.069298" z="0.163457" active="1" name="left_hand_tip"/>
 <point x="-0.221082" y="0.069179" z="0.163424" active="1" name="right_hand_tip"/>
 <point x="-0.002842" y="0.062211" z="0.076095" active="1" name="chest"/>
 <point x="0.007206" y="-0.110421" z="0.118022" active="1" name="navel"/>
 <point x="0.000481" y="0.071374" z="-0.106950" active="1" name="upper_back"/>
 <point x="-0.002685" y="-0.259030" z="-0.031047" active="1" name="crotch"/>
 <point x="0.140501" y="-0.202563" z="-0.024280" active="1" name="left_hip"/>
 <point x="-0.137942" y="-0.204104" z="-0.029934" active="1" name="right_hip"/>
 <point x="0.078397" y="-0.314118" z="0.045010" active="1" name="left_knee"/>
 <point x="-0.077496" y="-0.314075" z="0.045156" active="1" name="right_knee"/>
 <point x="0.094308" y="-0.490944" z="-0.085989" active="1" name="left_heel"/>
 <point x="-0.074023" y="-0.491648" z="-0.088219" active="1" name="right_heel"/>
 <point x="0.034295" y="-0.481287" z="0.110319" active="1" name="left_toe"/>
 <point x="-0.042859" y="-0.480662" z="0.110837" active="1" name="right_toe"/>
</PickedPoints>
