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
 <point x="-0.004747" y="0.404671" z="0.041978" active="1" name="head_top~nose_tip@50"/>
 <point x="0.074427" y="0.320759" z="0.034418" active="1" name="left_ear~nose_tip@50"/>
 <point x="-0.069494" y="0.321302" z="0.040151" active="1" name="right_ear~nose_tip@50"/>
 <point x="0.015170" y="0.111055" z="0.066653" active="1" name="chin~chest@50"/>
 <point x="-0.044758" y="0.289561" z="-0.097870" active="1" name="head_top~upper_back@50"/>
 <point x="0.085353" y="0.251909" z="-0.034806" active="1" name="left_ear~left_shoulder@50"/>
 <point x="-0.083213" y="0.251880" z="-0.032970" active="1" name="right_ear~right_shoulder@50"/>
 <point x="0.164239" y="0.119838" z="-0.050256" active="1" name="left_shoulder~left_elbow@33"/>
 <point x="0.204906" y="0.085886" z="-0.050339" active="1" name="left_shoulder~left_elbow@67"/>
 <point x="-0.160697" y="0.117245" z="-0.058860" active="1" name="right_shoulder~right_elbow@33"/>
 <point x="-0.196724" y="0.085724" z="-0.059240" active="1" name="right_shoulder~right_elbow@67"/>
 <point x="0.242812" y="0.070146" z="0.008268" active="1" name="left_elbow~left_wrist@50"/>
 <point x="-0.240710" y="0.072996" z="0.013150" active="1" name="right_elbow~right_wrist@50"/>
 <point x="0.244428" y="0.095935" z="0.130235" active="1" name="left_wrist~left_hand_tip@50"/>
 <point x="-0.244364" y="0.099067" z="0.121922" active="1" name="right_wrist~right_hand_tip@50"/>
 <point x="0.069289" y="0.127319" z="0.033565" active="1" name="chest~left_shoulder@50"/>
 <point x="-0.063801" y="0.119656" z="0.040085" active="1" name="chest~right_shoulder@50"/>
 <point x="0.057989" y="0.120398" z="-0.083779" active="1" name="upper_back~left_shoulder@50"/>
 <point x="-0.074491" y="0.106758" z="-0.081160" active="1" name="upper_back~right_shoulder@50"/>
 <point x="-0.007709" y="-0.002422" z="0.096190" active="1" name="chest~navel@50"/>
 <point x="0.028443" y="-0.208313" z="0.056973" active="1" name="navel~crotch@50"/>
 <point x="-0.005847" y="-0.046606" z="-0.140733" active="1" name="upper_back~crotch@33"/>
 <point x="0.000812" y="-0.176650" z="-0.138864" active="1" name="upper_back~crotch@67"/>
 <point x="0.110696" y="-0.046525" z="0.044321" active="1" name="chest~left_hip@50"/>
 <point x="-0.098527" y="-0.047053" z="0.059668" active="1" name="chest~right_hip@50"/>
 <point x="0.114237" y="-0.047262" z="-0.069676" active="1" name="upper_back~left_hip@50"/>
 <point x="-0.113315" y="-0.045149" z="-0.065277" active="1" name="upper_back~right_hip@50"/>
 <point x="0.101835" y="-0.006949" z="-0.069618" active="1" name="left_shoulder~left_hip@50"/>
 <point x="-0.106450" y="-0.005837" z="-0.052877" active="1" name="right_shoulder~right_hip@50"/>
 <point x="0.125338" y="-0.228591" z="0.013894" active="1" name="left_hip~left_knee@33"/>
 <point x="0.092643" y="-0.261250" z="0.032945" active="1" name="left_hip~left_knee@67"/>
 <point x="-0.124268" y="-0.241376" z="0.010687" active="1" name="right_hip~right_knee@33"/>
 <point x="-0.098622" y="-0.286975" z="0.030520" active="1" name="right_hip~right_knee@67"/>
 <point x="0.033039" y="-0.280061" z="0.016549" active="1" name="crotch~left_knee@50"/>
 <point x="-0.030062" y="-0.290312" z="0.014186" active="1" name="crotch~right_knee@50"/>
 <point x="0.057970" y="-0.418620" z="0.040435" active="1" name="left_knee~left_toe@50"/>
 <point x="-0.065109" y="-0.419091" z="0.043001" active="1" name="right_knee~right_toe@50"/>
 <point x="0.068546" y="-0.484944" z="0.020741" active="1" name="left_heel~left_toe@50"/>
 <point x="-0.048773" y="-0.487217" z="0.004568" active="1" name="right_heel~right_toe@50"/>
 <point x="0.137754" y="-0.333614" z="-0.061827" active="1" name="left_hip~left_heel@50"/>
 <point x="-0.133060" y="-0.346386" z="-0.067015" active="1" name="right_hip~right_heel@50"/>
 <point x="0.114724" y="-0.430638" z="-0.084863" active="1" name="left_hip~left_heel@80"/>
 <point x="-0.098259" y="-0.443365" z="-0.089328" active="1" name="right_hip~right_heel@80"/>
 <point x="0.086258" y="-0.216061" z="-0.095393" active="1" name="upper_back~crotch@67~left_hip@50"/>
 <point x="-0.073397" y="-0.209909" z="-0.103857" active="1" name="upper_back~crotch@67~right_hip@50"/>
</PickedPoints>
